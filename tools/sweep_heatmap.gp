# The heat map of `drape sweep` over a grid of two axes: one cell per grid point, coloured by the
# response, its value written in the cell; cells without a value are left blank.
# Variables: input (data file: i j value, the cell's positions along the two axes), xtics, ytics
# (gnuplot tic lists: ("label" 0, "label" 1, ...)), xlabel, ylabel, title, cblabel, output.
if (!exists("input")) { print "sweep_heatmap.gp: set input"; exit status 2 }
if (!exists("output")) { output = "heatmap.png" }
if (!exists("xlabel")) { xlabel = "" }
if (!exists("ylabel")) { ylabel = "" }
if (!exists("title")) { title = "" }
if (!exists("cblabel")) { cblabel = "" }
set terminal pngcairo size 850,650 enhanced font "sans,11"
set output output
set title title noenhanced
set xlabel xlabel noenhanced
set ylabel ylabel noenhanced
set cblabel cblabel noenhanced
if (exists("xtics")) { eval("set xtics " . xtics) }
if (exists("ytics")) { eval("set ytics " . ytics) }
stats input using 1:2 nooutput
set xrange [STATS_min_x - 0.5 : STATS_max_x + 0.5]
set yrange [STATS_min_y - 0.5 : STATS_max_y + 0.5]
set palette rgbformulae 33,13,10
set key off
plot input using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder palette, \
     input using 1:2:(sprintf("%.3g", $3)) with labels font "sans,10"
