# Plots t10-bench's times.dat (one row per frame size, one column per chain) on log-log axes.
# usage: gnuplot -e "dir='out/bench'" tools/bench/plot.gp   (writes dir/bench.png)
if (!exists("dir")) dir = "out/bench"
set terminal pngcairo size 1100,700 noenhanced font "DejaVu Sans,11"
set output dir."/bench.png"
set title "Post-process chains on the same HDR frames (median GL_TIME_ELAPSED)"
set logscale xy
set xlabel "pixels"
set ylabel "ms per frame"
set key outside right
set grid
plot for [i=2:*] dir."/times.dat" using 1:i with linespoints lw 2 title columnheader(i)
