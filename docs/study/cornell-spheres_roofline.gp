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
2014 2.79782e+09 2.82874e+08 NaN
2016 4.98419e+09 4.04105e+08 NaN
2018 6.68918e+10 5.65748e+08 8e+09
2020 1.09509e+11 9.5975e+08 1.33672e+10
2022 1.79294e+11 9.05196e+08 2.59738e+10
2025 2.07028e+11 1.21232e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.40092e+09 4.24942e+08 NaN
2017 6.36986e+09 6.1121e+08 NaN
2018 8.93421e+10 7.77903e+08 1e+10
2020 1.30897e+11 1.18201e+09 1.59024e+10
2022 3.03778e+11 1.27293e+09 4.40196e+10
2025 3.85363e+11 2.26299e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_naive.png'
set title "cornell-spheres, naive: rays/s that 1080p60 needs against each GPU's limits (3.58 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.70351e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 8.32e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.51519e+09 2.72465e+08 NaN
2016 4.48071e+09 3.89236e+08 NaN
2018 4.37775e+10 5.44931e+08 8e+09
2020 6.47145e+10 9.24436e+08 1.33672e+10
2022 1.05954e+11 8.71889e+08 2.59738e+10
2025 1.48907e+11 1.16771e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.05738e+09 4.09306e+08 NaN
2017 5.72641e+09 5.8872e+08 NaN
2018 5.84701e+10 7.4928e+08 1e+10
2020 7.73535e+10 1.13852e+09 1.59024e+10
2022 1.79518e+11 1.22609e+09 4.40196e+10
2025 2.77177e+11 2.17972e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bsdf.png'
set title "cornell-spheres, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.59 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.31231e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 5.18e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.65001e+09 2.94365e+08 NaN
2016 4.72087e+09 4.20522e+08 NaN
2018 3.50467e+10 5.8873e+08 8e+09
2020 5.18081e+10 9.98739e+08 1.33672e+10
2022 8.48231e+10 9.41968e+08 2.59738e+10
2025 1.24069e+11 1.26156e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.22125e+09 4.42205e+08 NaN
2017 6.03334e+09 6.36039e+08 NaN
2018 4.68091e+10 8.09504e+08 1e+10
2020 6.19265e+10 1.23003e+09 1.59024e+10
2022 1.43715e+11 1.32464e+09 4.40196e+10
2025 2.30943e+11 2.35492e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_nee.png'
set title "cornell-spheres, nee: rays/s that 1080p60 needs against each GPU's limits (5.66 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     5.86209e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 8.32e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.70322e+09 2.96259e+08 NaN
2016 4.81567e+09 4.23227e+08 NaN
2018 4.42048e+10 5.92517e+08 8e+09
2020 6.53463e+10 1.00516e+09 1.33672e+10
2022 1.06989e+11 9.48028e+08 2.59738e+10
2025 1.57157e+11 1.26968e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.28594e+09 4.45049e+08 NaN
2017 6.1545e+09 6.4013e+08 NaN
2018 5.90409e+10 8.14711e+08 1e+10
2020 7.81087e+10 1.23794e+09 1.59024e+10
2022 1.8127e+11 1.33316e+09 4.40196e+10
2025 2.92534e+11 2.37007e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bdpt.png'
set title "cornell-spheres, bdpt: rays/s that 1080p60 needs against each GPU's limits (11.99 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.28478e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 8.61e+03 spp'
