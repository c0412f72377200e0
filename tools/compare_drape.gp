# A drape of `drape compare`: the nodes in 3-D, coloured by the fourth column (height for the
# reference, distance to the reference for a deviating run).
# Variables: input (x y z colour), output (PNG), title, colour (colour bar label).
if (!exists("input")) { print "compare_drape.gp: set input"; exit status 2 }
if (!exists("output")) { output = "drape.png" }
if (!exists("title")) { title = "" }
if (!exists("colour")) { colour = "" }
set terminal pngcairo size 900,700 enhanced font "sans,11"
set output output
set title title noenhanced
set xlabel "x (m)"
set ylabel "y (m)"
set zlabel "z (m)" rotate parallel
set cblabel colour noenhanced
set view 60, 30
# One cube around the data, so that a flat drape keeps its proportions and readable ticks.
stats input using 1:2 nooutput
x_mid = (STATS_min_x + STATS_max_x) / 2; y_mid = (STATS_min_y + STATS_max_y) / 2
extent = STATS_max_x - STATS_min_x > STATS_max_y - STATS_min_y ? STATS_max_x - STATS_min_x : STATS_max_y - STATS_min_y
stats input using 3 nooutput
z_mid = (STATS_min + STATS_max) / 2
extent = extent > STATS_max - STATS_min ? extent : STATS_max - STATS_min
half = extent > 0 ? 0.52 * extent : 0.5
set xrange [x_mid - half : x_mid + half]
set yrange [y_mid - half : y_mid + half]
set zrange [z_mid - half : z_mid + half]
set palette rgbformulae 33,13,10
set ticslevel 0
splot input using 1:2:3:4 with points pointtype 7 pointsize 0.8 palette notitle
