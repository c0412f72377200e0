# Draws one drape of docs/netlogo.md: a 3-D view of the mesh's triangles (left) and their vertical
# projection, the shadow whose area makes the drape coefficient (right), with the flat disc's
# outline (radius 0.15 m) for scale. Input: blocks of closed triangles, "x y z" per line
# (written by tools/netlogo_report.cc).
#   gnuplot -e "input='arc.dat'; output='arc.png'; title='arc'" tools/netlogo_drape.gp
if (!exists("input")) { print "netlogo_drape.gp: set input='file.dat'"; exit status 2 }
if (!exists("output")) { output = "drape.png" }
if (!exists("title")) { title = "" }
set terminal pngcairo size 1100,500 enhanced font "sans,10"
set output output
set multiplot layout 1,2 title title
set view 65, 30
set xrange [-0.16:0.16]
set yrange [-0.16:0.16]
set zrange [-0.2:0.01]
set xlabel "x (m)"
set ylabel "y (m)"
set zlabel "z (m)" rotate parallel
set ticslevel 0
unset key
set palette rgbformulae 33,13,10
set cbrange [-0.2:0]
unset colorbox
splot input using 1:2:3:3 with lines lc palette lw 0.6
unset zlabel
set size ratio -1
set xrange [-0.16:0.16]
set yrange [-0.16:0.16]
set object 1 circle at 0,0 size 0.15 fs empty border rgb "gray50" dt 2
set title "vertical projection (shadow)"
plot input using 1:2 with filledcurves closed fc rgb "#4477aa" fs solid 0.6 noborder, \
     input using 1:2 with lines lc rgb "#223355" lw 0.3
unset multiplot
