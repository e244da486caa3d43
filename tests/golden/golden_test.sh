#!/usr/bin/env bash
# Renders one stage at the golden settings and compares it with tests/golden/<stage>.png.
# usage: golden_test.sh BIN_DIR OUT_DIR STAGE [--golden OTHER_STAGE] [extra stage arguments...]
# --golden compares against another stage's golden (a program that must reproduce that frame).
set -euo pipefail
bin=$1 out=$2 stage=$3
shift 3
golden=$stage
if [ "${1:-}" = "--golden" ]; then
    golden=$2
    shift 2
fi
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
# shellcheck source=render_args.sh
. "$here/render_args.sh"
"$bin/$stage" "${T10_GOLDEN_ARGS[@]}" "$@" --output "$out/$stage.png"
"$bin/imgcompare" "$here/$golden.png" "$out/$stage.png" "$here/$golden.tolerance" --diff-prefix "$out/$stage"
