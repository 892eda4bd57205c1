set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 66.23376623 5.424681453
1 70.37037037 6.272202843
EOD
$p1 << EOD
0 1.275126283 0.2191630378
1 1.46147033 0.3574513467
EOD
$p2 << EOD
0 1.120745135 0.2801636168
1 0.5507931332 0.1071210158
EOD
$p3 << EOD
0 1.222997584 0.1723905741
1 1.191640049 0.2588330082
EOD
$p4 << EOD
0 65.91666667 7.298041012
1 71.5 5.847601598
EOD
$p5 << EOD
0 7.7 0.6333333333
1 10.8 1.240967365
EOD
set multiplot layout 2,3 title "Section 4: new champions (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent (sparse start)" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 77 / 54, p = 0.6207" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with a different\ntopology (pooled) (fitness units)\nn = 51 / 38, p = 0.6419" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with the same topology\n(pooled) (fitness units)\nn = 26 / 16, p = 0.1297" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of any new champion (pooled) (fitness\nunits)\nn = 77 / 54, p = 0.9166" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a run's new champions with a different topology (per\nrun) (%)\nn = 10 / 5, p = 0.6278" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 10 / 5, p = 0.0268  *" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
