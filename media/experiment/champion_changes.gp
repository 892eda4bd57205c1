set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "champion_changes.png"
$p0 << EOD
0 60.37735849 4.773249298
1 61 4.9020713
EOD
$p1 << EOD
0 0.7068264237 0.110819367
1 0.6777136389 0.1078186923
EOD
$p2 << EOD
0 0.3733483867 0.05441975348
1 0.4987358387 0.1468660497
EOD
$p3 << EOD
0 0.5746936166 0.07183670125
1 0.6079122968 0.08719842309
EOD
$p4 << EOD
0 60.15792541 3.302196449
1 63.65909091 4.407403629
EOD
$p5 << EOD
0 10.6 0.7023769169
1 10 1.211060142
EOD
set multiplot layout 2,3 title "Section 4: new champions (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "new champions whose topology differs from the previous\nchampion's (pooled) (%)\nn = 106 / 100, p = 0.9276" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with a different\ntopology (pooled) (fitness units)\nn = 64 / 61, p = 0.8511" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of a new champion with the same topology\n(pooled) (fitness units)\nn = 42 / 39, p = 0.4129" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fitness improvement of any new champion (pooled) (fitness\nunits)\nn = 106 / 100, p = 0.768" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a run's new champions with a different topology (per\nrun) (%)\nn = 10 / 10, p = 0.5329" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "new champions per run\nn = 10 / 10, p = 0.6733" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
