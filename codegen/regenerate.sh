#!/usr/bin/env bash
# Regenerates the robot models of robots/*.toml (DH tables, or URDF files named by them).
# Usage, from anywhere:
#     bash codegen/regenerate.sh          # derives only the robots whose graphs are not current
#     bash codegen/regenerate.sh --all    # derives every robot (CI's drift check)
# A robot is kept as it is when both its graphs record its description's hash (TOML, and URDF
# if any) and the generator's (its Python modules and CasADi's version), and its URDF and C
# files exist.
#   1. codegen (Python + CasADi, codegen/requirements.txt) writes
#        generated/models/<robot>.json and <robot>_parametric.json  (the expression graphs),
#        generated/src/models.rs                 (one module per robot, and the registry of them),
#        generated/urdf/<robot>.urdf                                (each robot as a URDF),
#        generated/casadi_c/<robot>.c                               (CasADi's own C, benchmark only);
#   2. the proc-macro's snapshot test rewrites generated/expanded/*.rs, the formatted Rust that
#      the macro expands each graph to (for reading; `cargo test` checks it).
# Nothing is written if any description is invalid.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
PYTHONPATH="$root/codegen${PYTHONPATH:+:$PYTHONPATH}" python3 -m scara_codegen \
  --out generated/models --c-out generated/casadi_c --rust-index generated/src/models.rs \
  --urdf-out generated/urdf \
  --prune "$@" robots/*.toml
UPDATE_EXPANDED=1 cargo test --quiet -p scara-derive --lib snapshot >/dev/null
echo "regenerated generated/models, generated/src/models.rs, generated/casadi_c, generated/expanded"
