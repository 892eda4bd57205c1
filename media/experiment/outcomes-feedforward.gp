set terminal pngcairo enhanced size 1200,800 font "DejaVu Sans,11"
set output "outcomes-feedforward.png"
$shares << EOD
# generation, then cumulative per cent of the outcomes in generation_t's order
0 96.9 97.7 97.8 97.8 100 100
1 93.2 95.1 95.3 95.3 100 100
2 88.3 92.3 92.4 92.4 99.9 100
3 82.5 89.5 89.9 89.9 99.9 100
4 76.6 86 86.2 86.2 99.8 100
5 66.4 78.9 79.3 79.3 99.8 100
6 63.4 77.6 78.1 78.2 99.3 100
7 58.4 75.3 75.6 75.7 99.6 100
8 54.8 78.3 78.8 78.8 99.6 100
9 52.4 78.7 79.1 79.3 99.2 100
10 52.4 78.3 78.9 79.1 99.2 100
11 47.6 76.8 77.5 77.5 99.2 100
12 50.1 77.6 78.3 78.6 99.4 100
13 46.8 75.7 76.3 76.5 99.2 100
14 46.2 78.5 78.9 78.9 99.2 100
15 47.4 79.8 80.2 80.3 98.9 100
16 44.7 77.8 78.2 78.4 98.9 100
17 44 80.2 80.3 80.3 98.6 100
18 24.1 74.3 74.3 74.4 98.3 100
19 16.7 73 73.3 73.4 98.4 100
20 17.6 77.4 77.6 77.7 98.7 100
21 17.5 79.4 79.5 79.9 98.4 100
22 14.1 80.6 80.6 80.8 98.7 100
23 14.3 79 79.3 79.6 98 100
24 14.7 80.9 81 81.4 98.3 100
25 14.2 80.4 80.6 81.4 98.2 100
26 12.6 81.9 82 82 98.6 100
27 12.1 82.2 82.3 83 98.5 100
28 13.1 83.2 83.2 83.6 98.5 100
29 12.2 83.1 83.3 83.7 98.1 100
EOD
set title "Outcome shares per generation: feed-forward CPPNs"
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
