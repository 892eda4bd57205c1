set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "fig3_genotype.png"
$p0 << EOD
0 25.9 0.5149489429
1 25.3 0.6417468975
EOD
$p1 << EOD
0 1.833333333 0.3073181486
1 2.033333333 0.3088105968
EOD
$p2 << EOD
0 1.933333333 0.2534059182
1 1.8 0.3009563301
EOD
$p3 << EOD
0 2.133333333 0.2524971075
1 1.466666667 0.3060062855
EOD
$p4 << EOD
0 113.2333333 1.234264948
1 220.7 1.420012951
EOD
$p5 << EOD
0 113.2333333 1.234264948
1 109.3666667 1.186594987
EOD
$p6 << EOD
0 5.9 0.5149489429
1 5.3 0.6417468975
EOD
$p7 << EOD
0 0 0
1 111.3333333 0.2850018485
EOD
$p8 << EOD
0 0 0
1 112.4666667 0.4906794101
EOD
set multiplot layout 3,4 title "Figure 3: best-of-run CPPNs (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "nodes\nn = 30 / 30, p = 0.4688" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden sigmoid nodes\nn = 30 / 30, p = 0.6479" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden cosine nodes\nn = 30 / 30, p = 0.7359" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden Gaussian nodes\nn = 30 / 30, p = 0.0983" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "links (enabled)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "forward links (position of source < target)\nn = 30 / 30, p = 0.0277  *" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden nodes\nn = 30 / 30, p = 0.4688" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "recurrent links (not forward)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "links on a directed cycle\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
