"""Model generator: robot description (TOML) -> CasADi derivation -> expression graphs (JSON).

Pipeline (one module per phase):

1. ``description``  parse and validate ``robots/<name>.toml`` (exact numbers, clear errors);
2. ``derivation``   CasADi SX: DH frames, geometric Jacobian, recursive Newton-Euler, Christoffel C,
                    with sin/cos of each joint angle as plain symbols;
3. ``normalize``    replay each CasADi graph over exact polynomials, fold sin^2 + cos^2 = 1,
                    rebuild a compact CasADi graph (multivariate Horner + common subexpressions);
4. ``export``       CasADi instruction list -> JSON (``derive/FORMAT.md``), byte-identical for
                    identical input.

Run with ``bash codegen/regenerate.sh`` from the repository root.
"""

VERSION = "0.1.0"
GENERATOR = f"armdyn-codegen {VERSION}"
