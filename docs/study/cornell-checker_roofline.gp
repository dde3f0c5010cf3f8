# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot cornell-checker_roofline.gp
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
2014 3.47253e+09 3.04303e+08 NaN
2016 6.18617e+09 4.34718e+08 NaN
2018 6.8271e+10 6.08606e+08 8e+09
2020 1.12038e+11 1.03246e+09 1.33672e+10
2022 1.83436e+11 9.73769e+08 2.59738e+10
2025 2.11809e+11 1.30416e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.22109e+09 4.57134e+08 NaN
2017 7.90601e+09 6.57512e+08 NaN
2018 9.11842e+10 8.36833e+08 1e+10
2020 1.3392e+11 1.27155e+09 1.59024e+10
2022 3.10794e+11 1.36936e+09 4.40196e+10
2025 3.94264e+11 2.43442e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_naive.png'
set title "cornell-checker, naive: rays/s that 1080p60 needs against each GPU's limits (3.31 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.53874e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.16e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.17565e+09 2.97443e+08 NaN
2016 5.65728e+09 4.24919e+08 NaN
2018 4.51022e+10 5.94886e+08 8e+09
2020 6.66728e+10 1.00918e+09 1.33672e+10
2022 1.0916e+11 9.51817e+08 2.59738e+10
2025 1.53025e+11 1.27476e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.8602e+09 4.46828e+08 NaN
2017 7.23008e+09 6.42689e+08 NaN
2018 6.02395e+10 8.17968e+08 1e+10
2020 7.96944e+10 1.24289e+09 1.59024e+10
2022 1.8495e+11 1.33849e+09 4.40196e+10
2025 2.84843e+11 2.37954e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bsdf.png'
set title "cornell-checker, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.28 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.44817e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.55e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.0817e+09 3.02954e+08 NaN
2016 5.48992e+09 4.32792e+08 NaN
2018 3.60029e+10 6.05909e+08 8e+09
2020 5.32217e+10 1.02788e+09 1.33672e+10
2022 8.71375e+10 9.69454e+08 2.59738e+10
2025 1.27283e+11 1.29838e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.74601e+09 4.55108e+08 NaN
2017 7.0162e+09 6.54598e+08 NaN
2018 4.80863e+10 8.33125e+08 1e+10
2020 6.36161e+10 1.26592e+09 1.59024e+10
2022 1.47637e+11 1.3633e+09 4.40196e+10
2025 2.36926e+11 2.42364e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_nee.png'
set title "cornell-checker, nee: rays/s that 1080p60 needs against each GPU's limits (5.16 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.41601e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 221 spp', \
     3.51711e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 54.8 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.12021e+09 2.99517e+08 NaN
2016 5.55851e+09 4.27881e+08 NaN
2018 4.23149e+10 5.99034e+08 8e+09
2020 6.25525e+10 1.01622e+09 1.33672e+10
2022 1.02414e+11 9.58454e+08 2.59738e+10
2025 1.50371e+11 1.28364e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.79281e+09 4.49944e+08 NaN
2017 7.10386e+09 6.47171e+08 NaN
2018 5.65168e+10 8.23672e+08 1e+10
2020 7.47693e+10 1.25155e+09 1.59024e+10
2022 1.7352e+11 1.34783e+09 4.40196e+10
2025 2.79903e+11 2.39614e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bdpt.png'
set title "cornell-checker, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.72 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.44266e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 108 spp', \
     3.25582e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 24.4 spp'
