# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot cornell-spheres_roofline.gp
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
2014 2.79543e+09 2.82594e+08 NaN
2016 4.97994e+09 4.03706e+08 NaN
2018 6.6858e+10 5.65188e+08 8e+09
2020 1.09454e+11 9.58801e+08 1.33672e+10
2022 1.79204e+11 9.04301e+08 2.59738e+10
2025 2.06924e+11 1.21112e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.39803e+09 4.24522e+08 NaN
2017 6.36444e+09 6.10605e+08 NaN
2018 8.9297e+10 7.77133e+08 1e+10
2020 1.30831e+11 1.18084e+09 1.59024e+10
2022 3.03625e+11 1.27167e+09 4.40196e+10
2025 3.8517e+11 2.26075e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_naive.png'
set title "cornell-spheres, naive: rays/s that 1080p60 needs against each GPU's limits (3.58 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.52696e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 7.93e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.50828e+09 2.71858e+08 NaN
2016 4.4684e+09 3.88368e+08 NaN
2018 4.37696e+10 5.43715e+08 8e+09
2020 6.47028e+10 9.22374e+08 1.33672e+10
2022 1.05935e+11 8.69945e+08 2.59738e+10
2025 1.48878e+11 1.1651e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.04898e+09 4.08393e+08 NaN
2017 5.71068e+09 5.87407e+08 NaN
2018 5.84596e+10 7.47609e+08 1e+10
2020 7.73396e+10 1.13598e+09 1.59024e+10
2022 1.79485e+11 1.22336e+09 4.40196e+10
2025 2.77122e+11 2.17486e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bsdf.png'
set title "cornell-spheres, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.58 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.36591e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 5.31e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.65217e+09 2.94616e+08 NaN
2016 4.72473e+09 4.2088e+08 NaN
2018 3.50534e+10 5.89233e+08 8e+09
2020 5.1818e+10 9.99591e+08 1.33672e+10
2022 8.48393e+10 9.42772e+08 2.59738e+10
2025 1.24098e+11 1.26264e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.22388e+09 4.42582e+08 NaN
2017 6.03827e+09 6.36582e+08 NaN
2018 4.6818e+10 8.10195e+08 1e+10
2020 6.19383e+10 1.23108e+09 1.59024e+10
2022 1.43743e+11 1.32577e+09 4.40196e+10
2025 2.30997e+11 2.35693e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_nee.png'
set title "cornell-spheres, nee: rays/s that 1080p60 needs against each GPU's limits (5.69 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     6.4897e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 9.17e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.70048e+09 2.95999e+08 NaN
2016 4.81079e+09 4.22855e+08 NaN
2018 4.42245e+10 5.91997e+08 8e+09
2020 6.53754e+10 1.00428e+09 1.33672e+10
2022 1.07036e+11 9.47196e+08 2.59738e+10
2025 1.57229e+11 1.26857e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.28261e+09 4.44659e+08 NaN
2017 6.14826e+09 6.39569e+08 NaN
2018 5.90672e+10 8.13996e+08 1e+10
2020 7.81435e+10 1.23685e+09 1.59024e+10
2022 1.81351e+11 1.33199e+09 4.40196e+10
2025 2.92667e+11 2.36799e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bdpt.png'
set title "cornell-spheres, bdpt: rays/s that 1080p60 needs against each GPU's limits (12.01 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.29209e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 8.64e+03 spp'
