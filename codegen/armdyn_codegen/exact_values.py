"""Values of a description file read exactly (numbers and angles as ``sympy`` rationals and
multiples of pi, the joint variable ``q``), checked against the accepted range, and shown in
messages as they were written."""

from __future__ import annotations

import decimal
import re
import unicodedata
from decimal import Decimal

import sympy as sp

# Accepted numbers (SI units, angles in rad): 0, or a magnitude from MIN_MAGNITUDE to
# MAX_MAGNITUDE, with at most MAX_DIGITS significant digits. The model's coefficients are
# products of at most three of them (m a^2, m g a, I + m c^2, ...) times sines and cosines,
# so they stay between about 1e-90 and 1e90, far inside the range of a double (2.2e-308 to
# 1.8e308): rounding them once, at the end, neither overflows nor underflows.
MIN_MAGNITUDE = Decimal("1e-30")
MAX_MAGNITUDE = Decimal("1e30")
MAX_DIGITS = 100
ACCEPTED_RANGE = "0 or between 1e-30 and 1e30 in magnitude"
_PI = Decimal("3.14159265358979323846264338327950288")
# Arithmetic for range checks only: wide enough that no exponent a TOML file can hold overflows.
_WIDE = decimal.Context(prec=40, Emax=decimal.MAX_EMAX, Emin=decimal.MIN_EMIN)


_ANGLE = re.compile(
    r"^\s*(?P<sign>[+-]?)\s*(?:(?P<num>\d+(?:\.\d*)?)\s*\*?\s*)?pi\s*(?:/\s*(?P<den>\d+))?\s*$"
)
_DEG = re.compile(r"^\s*(?P<val>[+-]?\d+(?:\.\d*)?(?:[eE][+-]?\d+)?)\s*deg\s*$")
_NUM = re.compile(r"^\s*[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\s*$")
_VAR = re.compile(r"^\s*q\s*(?:(?P<op>[+-])\s*(?P<rest>.+))?$")


class _Problems:
    def __init__(self) -> None:
        self.items: list[str] = []

    def add(self, where: str, rule: str) -> None:
        self.items.append(f"{where}: {rule}")


def _escape(ch: str) -> str:
    """One character of a string shown in a message: quotes, backslashes, control characters,
    line separators and direction marks escaped, so that a message stays one plain line."""
    if ch in '"\\':
        return "\\" + ch
    if unicodedata.category(ch) in ("Cc", "Zl", "Zp", "Cf", "Cs"):
        return f"\\u{ord(ch):04X}" if ord(ch) < 0x10000 else f"\\U{ord(ch):08X}"
    return ch


def _plain(text: str) -> str:
    """A key or name from the file, for a message: escaped as in ``_escape``, cut short."""
    out = "".join(_escape(ch) for ch in text[:40])
    return out + "..." if len(text) > 40 else out


def _show(value, depth: int = 0) -> str:
    """A TOML value as it would be written, cut short, for messages."""
    if isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, (int, Decimal)):
        text = str(value)
    elif isinstance(value, str):
        text = '"' + "".join(_escape(ch) for ch in value[:80]) + '"'
    elif isinstance(value, list):
        if depth >= 3:
            text = "[...]"
        else:
            items = [_show(v, depth + 1) for v in value[:8]] + (["..."] if len(value) > 8 else [])
            text = "[" + ", ".join(items) + "]"
    elif isinstance(value, dict):
        text = "a table {" + ", ".join(_plain(k) for k in sorted(value)[:8]) + "}"
    elif value is None:
        text = "nothing"
    else:
        text = f"{value} (a {type(value).__name__})"
    return text if len(text) <= 60 else text[:57] + "..."


# Characters that change the direction of text: rustc refuses them in the string literals and
# doc comments the generated code puts names and descriptions in.
_BIDI = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def _text_problem(text: str):
    """Why ``text`` cannot be a one-line name or description in generated code, or None."""
    for ch in text:
        if ch in "\n\r":
            return "must be one line of text"
        if ch in _BIDI:
            return (
                f"contains U+{ord(ch):04X}, a character that changes the direction of text "
                "(Rust refuses it in the generated code)"
            )
        if unicodedata.category(ch) == "Cc" and ch != "\t":
            return f"contains the control character U+{ord(ch):04X}"
    return None


def _decimal(dec: Decimal, shown: str, where: str, problems: _Problems, what: str,
             check_range: bool = True) -> bool:
    """Whether ``dec`` is an accepted number: finite, at most MAX_DIGITS significant digits
    and (with ``check_range``) in the accepted range."""
    if not dec.is_finite():
        problems.add(where, f"{what} must be finite, got {shown}")
        return False
    digits = "".join(map(str, dec.as_tuple().digits)).strip("0")
    if len(digits) > MAX_DIGITS:
        problems.add(
            where, f"{what} has {len(digits)} significant digits; at most {MAX_DIGITS} are accepted"
        )
        return False
    if check_range and not dec.is_zero() and not MIN_MAGNITUDE <= dec.copy_abs() <= MAX_MAGNITUDE:
        problems.add(
            where,
            f"{what} = {shown} is out of range: a number must be {ACCEPTED_RANGE} "
            "(SI units, angles in rad)",
        )
        return False
    return True


def _exact_number(value, where: str, problems: _Problems, what: str, strings: bool = False):
    """A TOML number -> exact Rational; None on error. ``strings``: also a numeric string
    (the text of an angle or of the offset in ``"q + 0.1"``)."""
    if isinstance(value, str) and not strings:
        hint = " (write the number without quotes)" if _NUM.match(value) else ""
        problems.add(where, f"{what} must be a number, not the string {_show(value)}{hint}")
        return None
    if isinstance(value, bool) or not isinstance(value, (int, Decimal, str)):
        problems.add(where, f"{what} must be a number, got {_show(value)}")
        return None
    if isinstance(value, str):
        if not _NUM.match(value):
            problems.add(where, f"{what} must be a number, got {_show(value)}")
            return None
        dec = Decimal(value.strip())
        shown = value.strip()
    else:
        dec = Decimal(value)
        shown = str(value)
    if not _decimal(dec, shown, where, problems, what):
        return None
    return sp.Rational(*dec.as_integer_ratio())


def _exact_angle(value, where: str, problems: _Problems, what: str):
    """A number (rad), or 'pi', '-pi/2', '7*pi/8', '30deg' -> exact sympy expression."""
    if isinstance(value, str):
        shown = value.strip()
        m = _ANGLE.match(value)
        if m:
            num, den = Decimal(m.group("num") or 1), Decimal(m.group("den") or 1)
            if not all(_decimal(x, shown, where, problems, what, False) for x in (num, den)):
                return None
            if den == 0:
                problems.add(where, f"{what}: division by zero in {_show(value)}")
                return None
            if not _decimal(_WIDE.divide(_WIDE.multiply(num, _PI), den), shown, where, problems, what):
                return None
            sign = -1 if m.group("sign") == "-" else 1
            return sign * sp.Rational(*num.as_integer_ratio()) * sp.pi / int(den)
        m = _DEG.match(value)
        if m:
            deg = Decimal(m.group("val"))
            if not _decimal(deg, shown, where, problems, what, False):
                return None
            if not _decimal(_WIDE.divide(_WIDE.multiply(deg, _PI), 180), shown, where, problems, what):
                return None
            return sp.Rational(*deg.as_integer_ratio()) * sp.pi / 180
        if _NUM.match(value):
            return _exact_number(value, where, problems, what, strings=True)
        problems.add(
            where,
            f"{what} must be a number (rad) or an angle such as \"pi/2\", \"-7*pi/8\", "
            f"\"30deg\"; got {_show(value)}",
        )
        return None
    return _exact_number(value, where, problems, what)


def _variable(value, where, problems, what, angle: bool):
    """'q', 'q + <offset>' -> (True, offset); a constant -> (False, value)."""
    if isinstance(value, str):
        m = _VAR.match(value)
        if m:
            if m.group("rest") is None:
                return True, sp.Integer(0)
            rest, label = m.group("rest"), f"{what} offset"
            if angle:
                off = _exact_angle(rest, where, problems, label)
            else:
                off = _exact_number(rest, where, problems, label, strings=True)
            if off is None:
                return True, None
            return True, off if m.group("op") == "+" else -off
    parse = _exact_angle if angle else _exact_number
    return False, parse(value, where, problems, what)


def _check_keys(table, allowed, where, problems):
    if not isinstance(table, dict):
        problems.add(where, f"expected a table, got {type(table).__name__}")
        return False
    for key in sorted(set(table) - allowed):
        problems.add(where, f"unknown key `{_plain(key)}` (allowed: {', '.join(sorted(allowed))})")
    return True


def _vector(value, n, where, problems, what):
    if not isinstance(value, list) or len(value) != n:
        problems.add(where, f"{what} must be a list of {n} numbers, got {_show(value)}")
        return None
    out = [_exact_number(v, where, problems, f"{what}[{i}]") for i, v in enumerate(value)]
    return None if any(v is None for v in out) else tuple(out)
