#!/usr/bin/env bash
# Renders one stage at the golden settings and compares it with tests/golden/<stage>.png.
# usage: golden_test.sh BIN_DIR OUT_DIR STAGE [extra stage arguments...]
set -euo pipefail
bin=$1 out=$2 stage=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
# shellcheck source=render_args.sh
. "$here/render_args.sh"
"$bin/$stage" "${T10_GOLDEN_ARGS[@]}" "$@" --output "$out/$stage.png"
"$bin/imgcompare" "$here/$stage.png" "$out/$stage.png" "$here/$stage.tolerance" --diff-prefix "$out/$stage"
