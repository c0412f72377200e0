# Convergence curves of `drape compare`: relative position error (RMS node distance to the
# reference / size) against time, one line per solver, log axes.
# Variables: files (space-separated data files: time_s rms_distance_rel relative_residual),
# titles (one word per file), output (PNG), title.
if (!exists("files") || !exists("titles")) { print "compare_curves.gp: set files and titles"; exit status 2 }
if (!exists("output")) { output = "curves.png" }
if (!exists("title")) { title = "" }
set terminal pngcairo size 900,600 enhanced font "sans,11"
set output output
set title title noenhanced
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "time (s)"
set ylabel "RMS distance to the reference / size"
set key outside right top noenhanced
set grid
# Colours repeat after 8 lines: later lines are dashed, and every line has its own point type.
dash(i) = i > 8 ? 2 : 1
plot for [i=1:words(files)] word(files, i) using 1:2 with linespoints linewidth 1.5 \
    dashtype dash(i) pointtype (i % 13 + 1) pointsize 0.7 pointinterval 20 title word(titles, i)
