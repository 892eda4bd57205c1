set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "fig3_genotype.png"
$p0 << EOD
0 22.2 0.4422166387
1 22.1 0.348010217
EOD
$p1 << EOD
0 0.7 0.2603416559
1 0.5 0.2236067977
EOD
$p2 << EOD
0 0.4 0.1632993162
1 0.8 0.2
EOD
$p3 << EOD
0 1.1 0.1795054936
1 0.8 0.3265986324
EOD
$p4 << EOD
0 102.8 0.5120763832
1 102.6 0.5206833117
EOD
$p5 << EOD
0 102.8 0.5120763832
1 102.6 0.5206833117
EOD
$p6 << EOD
0 2.2 0.4422166387
1 2.1 0.348010217
EOD
$p7 << EOD
0 0 0
1 0 0
EOD
set multiplot layout 2,4 title "Figure 3: best-of-run CPPNs (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "nodes\nn = 10 / 10, p = 0.8609" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden sigmoid nodes\nn = 10 / 10, p = 0.5673" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden cosine nodes\nn = 10 / 10, p = 0.1387" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden Gaussian nodes\nn = 10 / 10, p = 0.4313" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "links (enabled)\nn = 10 / 10, p = 0.7873" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "forward links (on no cycle)\nn = 10 / 10, p = 0.7873" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden nodes\nn = 10 / 10, p = 0.8609" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "recurrent links (on a cycle)\nn = 10 / 10" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
