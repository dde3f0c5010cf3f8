# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot sphere-1m_roofline.gp
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
2014 2.01324e+09 2.15397e+08 NaN
2016 3.5865e+09 3.0771e+08 NaN
2018 6.71821e+10 4.30794e+08 8e+09
2020 1.10048e+11 7.30812e+08 1.33672e+10
2022 1.80176e+11 6.89271e+08 2.59738e+10
2025 2.08046e+11 9.2313e+08 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.44722e+09 3.23576e+08 NaN
2017 4.5836e+09 4.65412e+08 NaN
2018 8.97299e+10 5.92342e+08 1e+10
2020 1.3154e+11 9.00052e+08 1.59024e+10
2022 3.05272e+11 9.69287e+08 4.40196e+10
2025 3.87258e+11 1.72318e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_naive.png'
set title "sphere-1m, naive: rays/s that 1080p60 needs against each GPU's limits (3.51 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.97979e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.83e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.84552e+09 2.09826e+08 NaN
2016 3.28771e+09 2.99751e+08 NaN
2018 4.4057e+10 4.19651e+08 8e+09
2020 6.51278e+10 7.11908e+08 1.33672e+10
2022 1.06631e+11 6.71442e+08 2.59738e+10
2025 1.49757e+11 8.99252e+08 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.24334e+09 3.15207e+08 NaN
2017 4.20174e+09 4.53373e+08 NaN
2018 5.88435e+10 5.7702e+08 1e+10
2020 7.78475e+10 8.76771e+08 1.59024e+10
2022 1.80664e+11 9.44215e+08 4.40196e+10
2025 2.7876e+11 1.6786e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bsdf.png'
set title "sphere-1m, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.49 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.8184e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 4.19e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.74639e+09 2.05287e+08 NaN
2016 3.11111e+09 2.93267e+08 NaN
2018 3.5348e+10 4.10574e+08 8e+09
2020 5.22535e+10 6.96509e+08 1.33672e+10
2022 8.55523e+10 6.56918e+08 2.59738e+10
2025 1.25101e+11 8.79801e+08 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.12284e+09 3.08389e+08 NaN
2017 3.97605e+09 4.43566e+08 NaN
2018 4.72115e+10 5.64539e+08 1e+10
2020 6.24589e+10 8.57806e+08 1.59024e+10
2022 1.44951e+11 9.23791e+08 4.40196e+10
2025 2.32865e+11 1.6423e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_nee.png'
set title "sphere-1m, nee: rays/s that 1080p60 needs against each GPU's limits (5.57 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.83946e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 266 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.67557e+09 1.97821e+08 NaN
2016 2.98495e+09 2.82601e+08 NaN
2018 4.17526e+10 3.95641e+08 8e+09
2020 6.17212e+10 6.71177e+08 1.33672e+10
2022 1.01053e+11 6.33026e+08 2.59738e+10
2025 1.48423e+11 8.47803e+08 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.03676e+09 2.97173e+08 NaN
2017 3.81481e+09 4.27434e+08 NaN
2018 5.57656e+10 5.44007e+08 1e+10
2020 7.37756e+10 8.26608e+08 1.59024e+10
2022 1.71214e+11 8.90193e+08 4.40196e+10
2025 2.76276e+11 1.58257e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bdpt.png'
set title "sphere-1m, bdpt: rays/s that 1080p60 needs against each GPU's limits (11.14 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.80276e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 130 spp', \
     7.03767e+10 with lines lc 'black' dt 4 lw 2 title 'need: bilateral, 50.8 spp', \
     5.37684e+10 with lines lc 'black' dt 5 lw 2 title 'need: atrous, 38.8 spp'
