set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 48.91178852 2.892399364
1 97.94444444 0.9962680469
EOD
$p1 << EOD
0 1.281431698 0.1252336987
1 2.223993353 0.2130183964
EOD
$p2 << EOD
0 0.6475290174 0.1043006942
1 2.5772051 1.495449468
EOD
$p3 << EOD
0 14 0.641478178
1 5.533333333 0.3857619221
EOD
$p4 << EOD
0 47.14285714 2.438668567
1 96.98795181 1.330601106
EOD
$p5 << EOD
0 1.275100126 0.1173387967
1 1.951112141 0.1748942742
EOD
$p6 << EOD
0 0.5471560397 0.0515525511
1 2.241551587 1.206998095
EOD
$p7 << EOD
0 0.8903296802 0.06409246605
1 1.959860318 0.1727611202
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
set title "a run's mean fitness gain of its new champions with the same\ntopology (per run) (fitness units)\nn = 30 / 4, p = 0.0018  **" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 420 / 166 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with a different topology\n(pooled) (fitness units)\nn = 198 / 161 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of a new champion with the same topology (pooled)\n(fitness units)\nn = 222 / 5 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness gain of any new champion (pooled) (fitness units)\nn = 420 / 166 (pooled, descriptive)" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
