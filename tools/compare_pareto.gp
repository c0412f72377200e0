# Pareto plot of `drape compare`: final relative position error against time, every run of every
# scene, one point style per solver, log axes.
# Variables: files (space-separated data files: time_s rms_distance_rel scene), titles, output.
if (!exists("files") || !exists("titles")) { print "compare_pareto.gp: set files and titles"; exit status 2 }
if (!exists("output")) { output = "pareto.png" }
set terminal pngcairo size 900,600 enhanced font "sans,11"
set output output
set title "time against final error (every solver, every scene)"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "time (s)"
set ylabel "final RMS distance to the reference / size"
set key outside right top noenhanced
set grid
plot for [i=1:words(files)] word(files, i) using 1:2 with points pointsize 1.3 pointtype (i % 13 + 1) title word(titles, i)
