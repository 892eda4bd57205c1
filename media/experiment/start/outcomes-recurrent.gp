set terminal pngcairo enhanced size 1200,800 font "DejaVu Sans,11"
set output "outcomes-recurrent.png"
$shares << EOD
# generation, then cumulative per cent of the outcomes in generation_t's order
0 88.2 93.1 93.3 93.3 99.7 100
1 77.4 88.6 88.8 88.8 99.2 100
2 63.6 84.9 85 85 98.9 100
3 59.2 81.3 81.4 81.4 98.6 100
4 49.1 75.3 75.6 75.6 98.3 100
5 47.5 75.5 75.7 75.7 97.2 100
6 45.3 77.5 78.1 78.1 97.5 100
7 44.9 77.9 78 78 98.2 100
8 41 75.1 75.3 75.3 97.6 100
9 38.2 77.2 77.4 77.4 97.3 100
10 38.8 78.4 78.5 78.5 96.9 100
11 40.1 78.2 78.7 78.7 96.8 100
12 41.8 80 80.5 80.5 98.1 100
13 39.2 78.7 79.2 79.2 97.1 100
14 39.9 78 78.5 78.6 97.2 100
15 39 76.3 76.6 76.6 96 100
16 38.4 78.4 78.6 78.6 96.4 100
17 36.7 77.2 77.5 77.5 95.9 100
18 33.3 78.2 78.8 78.8 95.6 100
19 29.8 74 74.5 74.6 94.8 100
20 28 74.1 74.4 74.5 95.5 100
21 28.8 74.5 74.7 74.7 95 100
22 27.9 73.2 73.4 73.4 95.5 100
23 26.9 73.3 73.8 73.9 95.6 100
24 24.5 73.6 73.8 73.8 94.3 100
25 23.8 73.7 74 74 93.8 100
26 25.3 72.4 72.5 72.7 94.6 100
27 25.1 72.5 72.9 72.9 94.4 100
28 26.5 72.5 72.8 72.8 94.3 100
29 25.2 71.7 72.1 72.2 94.2 100
EOD
set title "Outcome shares per generation: recurrent CPPNs"
set xlabel "generation"
set ylabel "share of the population (%)"
set yrange [0:100]
set key outside right
set style fill solid 0.8 noborder
plot $shares using 1:7 with filledcurves x1 lc rgb "#9467bd" title "rolling (spin)", \
     $shares using 1:6 with filledcurves x1 lc rgb "#ff7f0e" title "rolling (contact)", \
     $shares using 1:5 with filledcurves x1 lc rgb "#d62728" title "acceleration fault", \
     $shares using 1:4 with filledcurves x1 lc rgb "#1f77b4" title "stopped early", \
     $shares using 1:3 with filledcurves x1 lc rgb "#2ca02c" title "completed", \
     $shares using 1:2 with filledcurves x1 lc rgb "#bbbbbb" title "not simulated"
unset output
