# Pareto plot of `drape compare`: final relative position error against time, every run of every
# scene, one colour per solver and one marker per scene, log axes.
# Variables: files (space-separated data files: time_s rms_distance_rel scene point_type), titles
# (one solver name per file), scenes (one word per scene, in the order of their point types),
# output.
if (!exists("files") || !exists("titles")) { print "compare_pareto.gp: set files and titles"; exit status 2 }
if (!exists("output")) { output = "pareto.png" }
if (!exists("scenes")) { scenes = "" }
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
# The legend: each solver as a filled square in its colour, each scene as its marker in black.
plot for [i=1:words(files)] word(files, i) using 1:2:4 with points pointsize 1.3 \
       pointtype variable linecolor i notitle, \
     for [i=1:words(files)] NaN with points pointsize 1.3 pointtype 5 linecolor i \
       title word(titles, i), \
     for [j=1:words(scenes)] NaN with points pointsize 1.3 pointtype ((j - 1) % 13 + 1) \
       linecolor rgb "black" title word(scenes, j)
