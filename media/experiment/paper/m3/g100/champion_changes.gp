set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 52.68287155 1.996950107
1 99.52380952 0.4761904762
EOD
$p1 << EOD
0 1.661934625 0.1128003562
1 2.668831713 0.2440420116
EOD
$p2 << EOD
0 1.065254174 0.1098206436
1 3.420971128 0
EOD
$p3 << EOD
0 18.1 0.7479473827
1 5.833333333 0.4550693602
EOD
$p4 << EOD
0 51.93370166 2.146077172
1 99.42857143 0.5714285714
EOD
$p5 << EOD
0 1.627623146 0.1199717369
1 2.316756411 0.1882229883
EOD
$p6 << EOD
0 0.967757673 0.07284049933
1 3.420971128 0
EOD
$p7 << EOD
0 1.310450239 0.07279627154
1 2.32306621 0.1872506787
EOD
set multiplot layout 3,3 title "Section 4: new champions (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "share of a run's new champions whose topology differs from the\nprevious champion's (per run) (%)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with a\ndifferent topology (per run) (fitness units)\nn = 30 / 30, p = 0.0004  ***" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with the same\ntopology (per run) (fitness units)\nn = 30 / 1, p = 0.0006  ***" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 543 / 175 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with a different topology\n(pooled) (fitness units)\nn = 282 / 174 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with the same topology (pooled)\n(fitness units)\nn = 261 / 1 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of any new champion (pooled) (fitness units)\nn = 543 / 175 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
