set terminal svg size 900,560 font 'sans,12'
set output 'docs/pareto.svg'
set logscale xy
set xlabel 'wall time of the command, s (2-core machine)'
set ylabel '|drape coefficient - reference|'
set grid
set key outside right
set arrow from graph 0, first 0.03 to graph 1, first 0.03 nohead dashtype 2
set label 'target 0.03' at graph 0.02, first 0.034
set arrow from 10, graph 0 to 10, graph 1 nohead dashtype 2
plot for [k=0:5] 'docs/pareto.svg.dat' index k using 1:2 with points pointsize 1.4 title columnheader(1)
