set terminal pngcairo enhanced size 1500,750 font "DejaVu Sans,11"
set output "fig3_genotype.png"
$p0 << EOD
0 21.9 0.2333333333
1 23.6 1.166190379
EOD
$p1 << EOD
0 0.7 0.2134374746
1 0.6 0.2449489743
EOD
$p2 << EOD
0 0.6 0.2666666667
1 1.6 0.6782329983
EOD
$p3 << EOD
0 0.6 0.2211083194
1 1.4 0.4
EOD
$p4 << EOD
0 103.9 0.5259911279
1 108 2.28035085
EOD
$p5 << EOD
0 103.9 0.5259911279
1 106.4 2.271563338
EOD
$p6 << EOD
0 1.9 0.2333333333
1 3.6 1.166190379
EOD
$p7 << EOD
0 0 0
1 1.6 0.5099019514
EOD
$p8 << EOD
0 0 0
1 0 0
EOD
set multiplot layout 3,4 title "Figure 3: best-of-run CPPNs (mean ± 1 s.e.)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent (sparse start)" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "nodes\nn = 10 / 5, p = 0.0699" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden sigmoid nodes\nn = 10 / 5, p = 0.7794" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden cosine nodes\nn = 10 / 5, p = 0.1195" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden Gaussian nodes\nn = 10 / 5, p = 0.0784" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "links (enabled)\nn = 10 / 5, p = 0.0335  *" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "forward links (position of source < target)\nn = 10 / 5, p = 0.1696" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "hidden nodes\nn = 10 / 5, p = 0.0699" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "recurrent links (not forward)\nn = 10 / 5, p = 0.0005  ***" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "links on a directed cycle\nn = 10 / 5" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
