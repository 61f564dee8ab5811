"""Model generator: robot description (TOML) -> CasADi derivation -> expression graphs (JSON).

Pipeline (one module per phase):

1. ``description``  parse and validate ``robots/<name>.toml`` (exact numbers, clear errors);
2. ``derivation``   CasADi SX: DH frames, geometric Jacobian, recursive Newton-Euler, Christoffel C,
                    with sin/cos of each joint angle as plain symbols;
3. ``normalize``    replay each CasADi graph over exact polynomials, fold sin^2 + cos^2 = 1,
                    rebuild a compact CasADi graph (multivariate Horner + common subexpressions);
4. ``export``       CasADi instruction list -> JSON (``derive/FORMAT.md``), byte-identical for
                    identical input.

The command ``armdyn-codegen`` (module ``cli``; ``python3 -m pip install ./codegen`` installs it,
``python3 -m armdyn_codegen`` is the same command) runs them on any description and writes the
graphs and the URDF into a folder of your choice; ``bash codegen/regenerate.sh`` runs it on the
registry of this repository (``robots/*.toml`` -> ``generated/``).
"""

VERSION = "0.1.0"
GENERATOR = f"armdyn-codegen {VERSION}"
