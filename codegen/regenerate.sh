#!/usr/bin/env bash
# Regenerates the robot models of robots/*.toml (DH tables, or URDF files named by them).
# Usage, from anywhere:
#     bash codegen/regenerate.sh          # derives only the robots whose graphs are not current
#     bash codegen/regenerate.sh --all    # derives every robot (CI's drift check)
# A robot is kept as it is when both its graphs record its description's hash (TOML, and URDF
# if any) and the generator's (its Python modules and CasADi's version), and its URDF and C
# files exist.
# It is a loop over the generator's command, `armdyn-codegen` (docs/generator.md), run from
# this tree (python3 -m armdyn_codegen with codegen/ first on PYTHONPATH, never an installed
# copy, whose generator hash could differ), with Python + CasADi (codegen/requirements.txt):
#   1. `--check` validates every description (and its task) and writes nothing: if one is
#      invalid, nothing is written at all;
#   2. one call per description writes
#        generated/models/<robot>.json and <robot>_parametric.json  (the expression graphs),
#        generated/urdf/<robot>.urdf                                (each robot as a URDF),
#        generated/casadi_c/<robot>.c                               (CasADi's own C, benchmark only);
#      (a robot that passes the check but still cannot be derived, such as a joint that moves
#      no mass, stops the loop there: its own files are not written, earlier robots' are);
#   3. `--index-only` writes generated/src/models.rs (one module per robot, and the registry of
#      them) and removes the models, URDFs and C files of robots that are no longer in robots/;
#   4. the proc-macro's snapshot test rewrites generated/expanded/*.rs, the formatted Rust that
#      the macro expands each graph to (for reading; `cargo test` checks it).
# Arguments (--all, --quiet) are passed to each call of step 2.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
export PYTHONPATH="$root/codegen${PYTHONPATH:+:$PYTHONPATH}"
codegen() { python3 -m armdyn_codegen "$@"; }
robots=(robots/*.toml)
folders=(--out generated/models --urdf-out generated/urdf --c-out generated/casadi_c)
codegen --check --quiet --out generated/models "${robots[@]}"
# One call per robot, two at a time (the derivations are single-threaded; ARMDYN_JOBS sets how
# many): the descriptions were all checked above, so a call that fails is a derivation's.
printf '%s\0' "${robots[@]}" \
  | xargs -0 -n 1 -P "${ARMDYN_JOBS:-2}" python3 -m armdyn_codegen "${folders[@]}" "$@"
codegen --index-only --quiet --rust-index generated/src/models.rs --prune "${folders[@]}" "${robots[@]}"
UPDATE_EXPANDED=1 cargo test --quiet -p armdyn-derive --lib snapshot >/dev/null
echo "regenerated generated/models, generated/urdf, generated/casadi_c, generated/src/models.rs, generated/expanded"
