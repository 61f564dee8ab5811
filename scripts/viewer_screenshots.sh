#!/usr/bin/env bash
# The viewer's screenshots in docs/figures/: tests/viewer.rs loads the thesis hybrid run and
# the Panda on its cylinder in headless Chromium, checks them and saves a screenshot of each
# (target/tmp/viewer/); this copies them into docs/figures/.
#
# Run: bash scripts/viewer_screenshots.sh   (needs chromium)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v chromium >/dev/null || { echo "error: chromium is not installed (apt-get install -y chromium)" >&2; exit 1; }
CI=true cargo test --release --test viewer -- --nocapture the_viewer_draws
for name in thesis-hybrid panda-cylinder; do
    cp "target/tmp/viewer/$name.png" "docs/figures/viewer-$name.png"
    echo "docs/figures/viewer-$name.png"
done
