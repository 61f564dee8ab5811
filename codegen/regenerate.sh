#!/usr/bin/env bash
# Regenerates every robot model from robots/*.toml:
#   1. codegen (Python + CasADi) writes generated/models/<robot>.json;
#   2. the proc-macro's snapshot test rewrites generated/expanded/<robot>.rs, the formatted
#      Rust that the macro expands to (for reading; checked by `cargo test`).
# Usage, from anywhere:  bash codegen/regenerate.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
PYTHONPATH="$root/codegen${PYTHONPATH:+:$PYTHONPATH}" python3 -m scara_codegen --out generated/models robots/*.toml
UPDATE_EXPANDED=1 cargo test --quiet -p scara-derive --lib expanded >/dev/null
echo "regenerated: generated/models/*.json and generated/expanded/*.rs"
