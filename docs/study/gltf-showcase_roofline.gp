# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot gltf-showcase_roofline.gp
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
2014 2.12689e+09 2.88212e+08 NaN
2016 3.78897e+09 4.11731e+08 NaN
2018 8.9496e+10 5.76424e+08 8e+09
2020 1.51272e+11 9.77861e+08 1.33672e+10
2022 2.47671e+11 9.22278e+08 2.59738e+10
2025 2.85981e+11 1.23519e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.58537e+09 4.32961e+08 NaN
2017 4.84236e+09 6.22743e+08 NaN
2018 1.19533e+11 7.92582e+08 1e+10
2020 1.80816e+11 1.20431e+09 1.59024e+10
2022 4.19628e+11 1.29695e+09 4.40196e+10
2025 5.32328e+11 2.30569e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_naive.png'
set title "gltf-showcase, naive: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.69115e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.06e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.06068e+09 2.88212e+08 NaN
2016 3.671e+09 4.11731e+08 NaN
2018 6.26405e+10 5.76424e+08 8e+09
2020 9.25991e+10 9.77861e+08 1.33672e+10
2022 1.51608e+11 9.22278e+08 2.59738e+10
2025 2.06872e+11 1.23519e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.50488e+09 4.32961e+08 NaN
2017 4.6916e+09 6.22743e+08 NaN
2018 8.36641e+10 7.92582e+08 1e+10
2020 1.10684e+11 1.20431e+09 1.59024e+10
2022 2.56869e+11 1.29695e+09 4.40196e+10
2025 3.85074e+11 2.30569e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bsdf.png'
set title "gltf-showcase, bsdf: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.69115e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.06e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.05012e+09 2.88605e+08 NaN
2016 3.6522e+09 4.12293e+08 NaN
2018 4.0372e+10 5.77211e+08 8e+09
2020 5.96803e+10 9.79197e+08 1.33672e+10
2022 9.77118e+10 9.23537e+08 2.59738e+10
2025 1.41231e+11 1.23688e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.49205e+09 4.33552e+08 NaN
2017 4.66757e+09 6.23594e+08 NaN
2018 5.39217e+10 7.93665e+08 1e+10
2020 7.13361e+10 1.20596e+09 1.59024e+10
2022 1.65553e+11 1.29872e+09 4.40196e+10
2025 2.6289e+11 2.30884e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_nee.png'
set title "gltf-showcase, nee: rays/s that 1080p60 needs against each GPU's limits (2.66 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     9.03641e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.73e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.32122e+09 3.27343e+08 NaN
2016 4.13516e+09 4.67633e+08 NaN
2018 4.27555e+10 6.54686e+08 8e+09
2020 6.32038e+10 1.11063e+09 1.33672e+10
2022 1.03481e+11 1.0475e+09 2.59738e+10
2025 1.51086e+11 1.4029e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.82159e+09 4.91745e+08 NaN
2017 5.28479e+09 7.07294e+08 NaN
2018 5.71052e+10 9.00193e+08 1e+10
2020 7.55477e+10 1.36783e+09 1.59024e+10
2022 1.75327e+11 1.47304e+09 4.40196e+10
2025 2.81233e+11 2.61874e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bdpt.png'
set title "gltf-showcase, bdpt: rays/s that 1080p60 needs against each GPU's limits (4.64 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     8.40003e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.45e+03 spp'
