set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 61.70212766 5.040758827
1 54.63917526 5.081090406
EOD
$p1 << EOD
0 0.741943087 0.1276840395
1 0.6915996362 0.1082120233
EOD
$p2 << EOD
0 0.4244529003 0.1051232447
1 0.4562075642 0.1103901461
EOD
$p3 << EOD
0 0.6203511006 0.08952300081
1 0.584823851 0.078004206
EOD
$p4 << EOD
0 62.05910756 7.58275792
1 56.16233766 4.063006031
EOD
$p5 << EOD
0 9.4 1.077032961
1 9.7 0.8950481055
EOD
set multiplot layout 2,3 title "Section 4: new champions (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 94 / 97, p = 0.3252" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with a different\ntopology (pooled) (fitness units)\nn = 58 / 53, p = 0.7663" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with the same topology\n(pooled) (fitness units)\nn = 36 / 44, p = 0.8379" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of any new champion (pooled) (fitness\nunits)\nn = 94 / 97, p = 0.7647" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a run's new champions with a different topology (per\nrun) (%)\nn = 10 / 10, p = 0.5018" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 10 / 10, p = 0.8328" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
