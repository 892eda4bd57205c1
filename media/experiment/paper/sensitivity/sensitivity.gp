set terminal pngcairo enhanced size 1200,800 font "DejaVu Sans,11"
set output "sensitivity.png"
set title "The gap at generation record 29, factor by factor, beside the reference's on the same seeds"
$factor << EOD
5 -3.349543963 -7.716669448 1.017581521
4 3.412170699 -1.153887792 7.97822919
3 5.719456737 1.412539879 10.02637359
2 7.342478991 3.259018243 11.42593974
1 4.280117872 0.6515857132 7.90865003
EOD
$reference << EOD
4.75 2.986754964 -1.278932718 7.252442647
3.75 2.986754964 -1.278932718 7.252442647
2.75 2.986754964 -1.278932718 7.252442647
1.75 2.986754964 -1.278932718 7.252442647
0.75 2.986754964 -1.278932718 7.252442647
EOD
set ytics ("bias-1.0" 5, "cap-100" 4, "no-contact-rule" 3, "proportional-weights" 2, "shared-add-node" 1)
set yrange [0.4:5.5]
set xlabel "gap in best-so-far fitness after 30 generations: feedforward mean minus recurrent mean, with its 95 % interval"
set grid xtics
set key outside top center horizontal
set arrow from 0, graph 0 to 0, graph 1 nohead dashtype 2 linecolor rgb "gray30"
plot $factor using 2:1:3:4 with xerrorbars pointtype 7 pointsize 1.4 linewidth 2 linecolor rgb "#c0392b" title "the factor changed", \
     $reference using 2:1:3:4 with xerrorbars pointtype 6 pointsize 1.4 linewidth 2 linecolor rgb "#2c3e50" title "the reference, the same seeds"
