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
2014 3.46949e+09 3.03975e+08 NaN
2016 6.18073e+09 4.34251e+08 NaN
2018 6.82363e+10 6.07951e+08 8e+09
2020 1.1198e+11 1.03135e+09 1.33672e+10
2022 1.8334e+11 9.72721e+08 2.59738e+10
2025 2.11699e+11 1.30275e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.21738e+09 4.56642e+08 NaN
2017 7.89907e+09 6.56804e+08 NaN
2018 9.11378e+10 8.35932e+08 1e+10
2020 1.3385e+11 1.27018e+09 1.59024e+10
2022 3.10632e+11 1.36789e+09 4.40196e+10
2025 3.94059e+11 2.4318e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_naive.png'
set title "cornell-checker, naive: rays/s that 1080p60 needs against each GPU's limits (3.31 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.56547e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.23e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.1769e+09 2.97576e+08 NaN
2016 5.6595e+09 4.25108e+08 NaN
2018 4.517e+10 5.95151e+08 8e+09
2020 6.6773e+10 1.00963e+09 1.33672e+10
2022 1.09324e+11 9.52242e+08 2.59738e+10
2025 1.53243e+11 1.27532e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.86172e+09 4.47028e+08 NaN
2017 7.23293e+09 6.42976e+08 NaN
2018 6.033e+10 8.18333e+08 1e+10
2020 7.98141e+10 1.24344e+09 1.59024e+10
2022 1.85228e+11 1.33909e+09 4.40196e+10
2025 2.85248e+11 2.38061e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bsdf.png'
set title "cornell-checker, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.27 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.49275e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.67e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.07947e+09 3.02712e+08 NaN
2016 5.48594e+09 4.32445e+08 NaN
2018 3.59487e+10 6.05423e+08 8e+09
2020 5.31416e+10 1.02706e+09 1.33672e+10
2022 8.70063e+10 9.68677e+08 2.59738e+10
2025 1.27095e+11 1.29734e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.74329e+09 4.54743e+08 NaN
2017 7.01111e+09 6.54073e+08 NaN
2018 4.80139e+10 8.32457e+08 1e+10
2020 6.35203e+10 1.2649e+09 1.59024e+10
2022 1.47414e+11 1.3622e+09 4.40196e+10
2025 2.36576e+11 2.42169e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_nee.png'
set title "cornell-checker, nee: rays/s that 1080p60 needs against each GPU's limits (5.16 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.42466e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 222 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.12026e+09 2.99502e+08 NaN
2016 5.5586e+09 4.2786e+08 NaN
2018 4.23286e+10 5.99004e+08 8e+09
2020 6.25727e+10 1.01617e+09 1.33672e+10
2022 1.02447e+11 9.58406e+08 2.59738e+10
2025 1.5042e+11 1.28358e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.79287e+09 4.49922e+08 NaN
2017 7.10397e+09 6.47138e+08 NaN
2018 5.6535e+10 8.23631e+08 1e+10
2020 7.47934e+10 1.25149e+09 1.59024e+10
2022 1.73576e+11 1.34776e+09 4.40196e+10
2025 2.79993e+11 2.39602e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bdpt.png'
set title "cornell-checker, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.72 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.53771e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 115 spp', \
     3.96906e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 29.8 spp'
