#!/usr/bin/env bash
# Re-records golden images on purpose: `make bless` (all stages) or `make bless STAGES=name`.
# Nothing else writes into tests/golden/. Review the new images before committing them.
# usage: bless.sh BIN_DIR STAGE...
set -euo pipefail
bin=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
. "$here/render_args.sh"
for stage in "$@"; do
    "$bin/$stage" "${T10_GOLDEN_ARGS[@]}" --output "$here/$stage.png"
    [ -f "$here/$stage.tolerance" ] || echo "note: $here/$stage.tolerance is missing; write one with reasons"
done
echo "Blessed: $*. Check the images and the tolerances before you commit."
