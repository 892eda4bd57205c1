set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 66.62746513 3.255052456
1 72.5993451 3.934537574
EOD
$p1 << EOD
0 1.25700573 0.1495154709
1 1.223015567 0.1528124205
EOD
$p2 << EOD
0 0.6927286143 0.1254883993
1 1.274272292 0.2821792845
EOD
$p3 << EOD
0 7.966666667 0.4380818517
1 8.433333333 0.5179165453
EOD
$p4 << EOD
0 65.27196653 3.086135327
1 73.51778656 2.779540983
EOD
$p5 << EOD
0 1.153240518 0.120172535
1 1.034318134 0.1243651065
EOD
$p6 << EOD
0 0.6152543534 0.08656209442
1 1.057951684 0.1836930922
EOD
$p7 << EOD
0 0.9664085029 0.08550510948
1 1.040576821 0.1033846084
EOD
set multiplot layout 3,3 title "Section 4: new champions (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent (sparse start)" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "share of a run's new champions whose topology differs from the\nprevious champion's (per run) (%)\nn = 30 / 30, p = 0.247" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with a\ndifferent topology (per run) (fitness units)\nn = 30 / 30, p = 0.8742" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with the same\ntopology (per run) (fitness units)\nn = 29 / 25, p = 0.0536" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 30 / 30, p = 0.4942" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 239 / 253 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with a different topology\n(pooled) (fitness units)\nn = 156 / 186 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with the same topology (pooled)\n(fitness units)\nn = 83 / 67 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of any new champion (pooled) (fitness units)\nn = 239 / 253 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
