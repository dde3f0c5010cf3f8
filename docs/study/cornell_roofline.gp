# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot cornell_roofline.gp
set terminal pngcairo size 900,560 font 'sans,10'
set grid
set key outside right top
set logscale y
set format y '10^{%T}'
set xlabel 'year'
set ylabel 'rays per second'
set xrange [2013.5:2025.5]

$naive_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.4662e+09 3.03639e+08 NaN
2016 6.17488e+09 4.3377e+08 NaN
2018 6.82445e+10 6.07279e+08 8e+09
2020 1.11971e+11 1.0302e+09 1.33672e+10
2022 1.83324e+11 9.71646e+08 2.59738e+10
2025 2.11681e+11 1.30131e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.21339e+09 4.56137e+08 NaN
2017 7.89159e+09 6.56078e+08 NaN
2018 9.11489e+10 8.35008e+08 1e+10
2020 1.33839e+11 1.26878e+09 1.59024e+10
2022 3.10606e+11 1.36638e+09 4.40196e+10
2025 3.94025e+11 2.42911e+09 7.32891e+10
EOD
set output 'cornell_roofline_naive.png'
set title "cornell, naive: rays/s that 1080p60 needs against each GPU's limits (3.34 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.94135e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 7.08e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.17469e+09 2.9732e+08 NaN
2016 5.65558e+09 4.24743e+08 NaN
2018 4.51547e+10 5.9464e+08 8e+09
2020 6.67504e+10 1.00876e+09 1.33672e+10
2022 1.09287e+11 9.51424e+08 2.59738e+10
2025 1.53222e+11 1.27423e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.85904e+09 4.46643e+08 NaN
2017 7.22791e+09 6.42423e+08 NaN
2018 6.03096e+10 8.1763e+08 1e+10
2020 7.97871e+10 1.24237e+09 1.59024e+10
2022 1.85165e+11 1.33794e+09 4.40196e+10
2025 2.8521e+11 2.37856e+09 7.32891e+10
EOD
set output 'cornell_roofline_bsdf.png'
set title "cornell, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.30 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.64926e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 4.02e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.07642e+09 3.0238e+08 NaN
2016 5.48051e+09 4.31972e+08 NaN
2018 3.5895e+10 6.0476e+08 8e+09
2020 5.30621e+10 1.02593e+09 1.33672e+10
2022 8.68762e+10 9.67616e+08 2.59738e+10
2025 1.26919e+11 1.29591e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.73959e+09 4.54245e+08 NaN
2017 7.00418e+09 6.53357e+08 NaN
2018 4.79421e+10 8.31545e+08 1e+10
2020 6.34254e+10 1.26352e+09 1.59024e+10
2022 1.47194e+11 1.36071e+09 4.40196e+10
2025 2.36248e+11 2.41904e+09 7.32891e+10
EOD
set output 'cornell_roofline_nee.png'
set title "cornell, nee: rays/s that 1080p60 needs against each GPU's limits (5.20 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.45173e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 224 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.11865e+09 2.99359e+08 NaN
2016 5.55574e+09 4.27656e+08 NaN
2018 4.2266e+10 5.98719e+08 8e+09
2020 6.24802e+10 1.01568e+09 1.33672e+10
2022 1.02296e+11 9.5795e+08 2.59738e+10
2025 1.50202e+11 1.28297e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.79092e+09 4.49707e+08 NaN
2017 7.10032e+09 6.4683e+08 NaN
2018 5.64514e+10 8.23238e+08 1e+10
2020 7.46829e+10 1.25089e+09 1.59024e+10
2022 1.7332e+11 1.34712e+09 4.40196e+10
2025 2.79588e+11 2.39487e+09 7.32891e+10
EOD
set output 'cornell_roofline_bdpt.png'
set title "cornell, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.76 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.6099e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 120 spp', \
     4.76298e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 35.6 spp'
