set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 57.79578876 2.267272539
1 100 0
EOD
$p1 << EOD
0 1.630025932 0.1148465384
1 2.723396255 0.2580411227
EOD
$p2 << EOD
0 1.157850316 0.1968066254
1 0 0
EOD
$p3 << EOD
0 14.16666667 0.7177284303
1 5 0.4341724855
EOD
$p4 << EOD
0 57.17647059 2.403073047
1 100 0
EOD
$p5 << EOD
0 1.542579836 0.1284008492
1 2.322797602 0.2097021803
EOD
$p6 << EOD
0 0.9772346071 0.09011794282
1 0 0
EOD
$p7 << EOD
0 1.300479056 0.08396100698
1 2.322797602 0.2097021803
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
set title "a run's mean fitness gain of its new champions with a\ndifferent topology (per run) (fitness units)\nn = 30 / 30, p = 0.0003  ***" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with the same\ntopology (per run) (fitness units)\nn = 30 / 0" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 425 / 150 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with a different topology\n(pooled) (fitness units)\nn = 243 / 150 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with the same topology (pooled)\n(fitness units)\nn = 182 / 0 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of any new champion (pooled) (fitness units)\nn = 425 / 150 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
