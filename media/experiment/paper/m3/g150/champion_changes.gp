set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 49.98860306 2.081685401
1 98.5515873 0.8130914682
EOD
$p1 << EOD
0 1.627097168 0.1065698809
1 2.672254689 0.2121609897
EOD
$p2 << EOD
0 1.055672887 0.1039575953
1 1.352696138 1.043115632
EOD
$p3 << EOD
0 21.9 1.048644445
1 6.3 0.4552377174
EOD
$p4 << EOD
0 49.01065449 1.951789827
1 98.41269841 0.9115413425
EOD
$p5 << EOD
0 1.555052526 0.1093881776
1 2.379676574 0.1826301148
EOD
$p6 << EOD
0 0.9505147721 0.06411253769
1 1.352696138 1.043115632
EOD
$p7 << EOD
0 1.246802682 0.0638435908
1 2.363375297 0.1804769054
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
set title "a run's mean fitness gain of its new champions with a\ndifferent topology (per run) (fitness units)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "a run's mean fitness gain of its new champions with the same\ntopology (per run) (fitness units)\nn = 30 / 3, p = 0.4989" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 657 / 189 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with a different topology\n(pooled) (fitness units)\nn = 322 / 186 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with the same topology (pooled)\n(fitness units)\nn = 335 / 3 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of any new champion (pooled) (fitness units)\nn = 657 / 189 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
