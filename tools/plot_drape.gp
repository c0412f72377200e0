# Draws a 3-D view of a drape result from its nodes.csv: every node coloured by its height, the
# fixed (or partly fixed) nodes as black squares, and the vertical shadow on the lowest level.
# Used by `drape solve` when `output.write` lists `png`; also usable by hand:
#   gnuplot -e "input='out/hanging_sheet/nodes.csv'; output='drape.png'" tools/plot_drape.gp
# Variables: input (nodes.csv, required), output (PNG path, default drape.png), title (optional).
# nodes.csv columns: 1 id, 2 i, 3 j, 4 x, 5 y, 6 z, 7 fixed ("xyz" letters, "" when free), 8-10 f.

if (!exists("input")) { print "plot_drape.gp: set input='nodes.csv'"; exit status 2 }
if (!exists("output")) { output = "drape.png" }
if (!exists("title")) { title = "" }

set datafile separator ","
set terminal pngcairo size 900,700 enhanced font "sans,11"
set output output

stats input using 4:5 skip 1 nooutput
x_min = STATS_min_x; x_max = STATS_max_x; y_min = STATS_min_y; y_max = STATS_max_y
stats input using 6 skip 1 nooutput
z_min = STATS_min; z_max = STATS_max
# Every axis spans at least a third of the largest extent, centred on the data, so that a flat
# result (a chain in the x-z plane, a sheet hanging in a vertical plane) keeps readable ticks.
extent = x_max - x_min > y_max - y_min ? x_max - x_min : y_max - y_min
extent = extent > z_max - z_min ? extent : z_max - z_min
extent = extent > 0 ? extent : 1
half(low, high) = (high - low) / 2 > extent / 6 ? (high - low) / 2 * 1.02 : extent / 6
set xrange [(x_min + x_max) / 2 - half(x_min, x_max) : (x_min + x_max) / 2 + half(x_min, x_max)]
set yrange [(y_min + y_max) / 2 - half(y_min, y_max) : (y_min + y_max) / 2 + half(y_min, y_max)]
set zrange [(z_min + z_max) / 2 - half(z_min, z_max) : (z_min + z_max) / 2 + half(z_min, z_max)]
set cbrange [(z_min + z_max) / 2 - half(z_min, z_max) : (z_min + z_max) / 2 + half(z_min, z_max)]
# One round tick step (1, 2 or 5 × 10^k) for all three axes, about four per largest extent.
magnitude = 10 ** floor(log10(extent / 4))
ratio = extent / 4 / magnitude
step = (ratio < 1.5 ? 1 : ratio < 3.5 ? 2 : 5) * magnitude
set xtics step
set ytics step
set ztics step
set xlabel "x (m)"
set ylabel "y (m)"
set zlabel "z (m)" rotate parallel
set view 62, 32
set view equal xyz
set ticslevel 0
set grid
set key top right
set palette rgbformulae 33,13,10
set cblabel "z (m)"
set title title noenhanced

is_fixed(col) = strlen(strcol(col)) > 0
splot input using 4:5:(z_min) skip 1 with points pt 7 ps 0.5 lc rgb "#d0d0d0" title "shadow", \
      input using 4:5:6:6 skip 1 with points pt 7 ps 0.9 lc palette title "nodes", \
      input using 4:5:(is_fixed(7) ? $6 : NaN) skip 1 with points pt 5 ps 1.6 lc rgb "black" \
            title "fixed"
