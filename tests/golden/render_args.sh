# The fixed settings every golden image is rendered with (sourced by golden_test.sh and bless.sh):
# Mesa llvmpipe through EGL, one frame, the default camera, a size small enough to keep CI quick.
T10_GOLDEN_ARGS=(--backend egl --size 640x360 --camera default --frames 1)
