# One response of `drape sweep` against one varied key: a point per task (sweep.csv's rows).
# Variables: input (data file: whitespace-separated columns, '?' where a value is missing), xcol,
# ycol (its columns), errcol (optional: a column of ± errors, drawn as bars; the y axis then
# autoscales within [0, 1], a drape coefficient's range), xlabel, ylabel, title, logx (1: log x
# axis), output.
if (!exists("input") || !exists("xcol") || !exists("ycol")) { print "sweep_scalar.gp: set input, xcol and ycol"; exit status 2 }
if (!exists("output")) { output = "scalar.png" }
if (!exists("xlabel")) { xlabel = "" }
if (!exists("ylabel")) { ylabel = "" }
if (!exists("title")) { title = "" }
if (!exists("logx")) { logx = "0" }
set terminal pngcairo size 800,550 enhanced font "sans,11"
set output output
set datafile missing "?"
set title title noenhanced
set xlabel xlabel noenhanced
set ylabel ylabel noenhanced
if (logx eq "1") { set logscale x }
set grid
set key off
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
if (exists("errcol")) {
  set yrange [0 < * : * < 1]
  plot input using (column(int(xcol))):(column(int(ycol))):(column(int(errcol))) with yerrorbars pointtype 7 pointsize 1.2 linecolor rgb "#1f5fa8"
} else {
  plot input using (column(int(xcol))):(column(int(ycol))) with points pointtype 7 pointsize 1.2 linecolor rgb "#1f5fa8"
}
