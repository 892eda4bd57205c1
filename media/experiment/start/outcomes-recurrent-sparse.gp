set terminal pngcairo enhanced size 1200,800 font "DejaVu Sans,11"
set output "outcomes-recurrent-sparse.png"
$shares << EOD
# generation, then cumulative per cent of the outcomes in generation_t's order
0 99 99 99.2 99.2 100 100
1 95.6 96.8 97 97 100 100
2 91.2 93.2 93.4 93.4 100 100
3 82 87.6 88 88 99.8 100
4 74.6 82.6 83.2 83.2 99.8 100
5 72.2 80.6 81.4 81.4 99.8 100
6 66.4 78.8 79.2 79.2 100 100
7 66 81.8 82.4 82.4 99 100
8 56.8 77 77.6 77.6 98.6 100
9 56.4 78.8 79 79 99.6 100
10 52.2 75.4 75.4 75.4 99.4 100
11 45.4 76.2 76.4 76.4 99.6 100
12 48.6 74.4 74.4 74.4 99.2 100
13 52.4 79.8 79.8 79.8 99.2 100
14 47.8 77.6 77.8 77.8 99.2 100
15 49.4 79 79 79 98.4 100
16 46.8 77 77 77 99.2 100
17 48.4 82.2 82.6 82.6 98.8 100
18 27.2 78 78.4 78.4 98.2 100
19 24 77.4 77.6 78 99 100
20 18.2 78.8 78.8 78.8 99 100
21 16.2 80.4 80.4 80.4 98.6 100
22 20.4 82.6 82.8 82.8 98.6 100
23 18.4 82.8 83 83 99.4 100
24 17.4 84 84 84 98.6 100
25 15.8 85.2 85.2 85.2 99.2 100
26 16.4 80.4 80.4 80.4 98.2 100
27 20.8 82.6 82.8 82.8 98.2 100
28 16.8 84 84.4 84.4 98.8 100
29 16.4 85 85.6 85.6 99 100
EOD
set title "Outcome shares per generation: recurrent (sparse start) CPPNs"
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
