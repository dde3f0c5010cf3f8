# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot environment_roofline.gp
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
2014 3.406e+09 4.45169e+08 NaN
2016 6.06763e+09 6.35955e+08 NaN
2018 1.08923e+11 8.90337e+08 8e+09
2020 1.88079e+11 1.51039e+09 1.33672e+10
2022 3.07933e+11 1.42454e+09 2.59738e+10
2025 3.55564e+11 1.90787e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.1402e+09 6.68747e+08 NaN
2017 7.75452e+09 9.61882e+08 NaN
2018 1.4548e+11 1.22421e+09 1e+10
2020 2.24811e+11 1.86017e+09 1.59024e+10
2022 5.21729e+11 2.00326e+09 4.40196e+10
2025 6.6185e+11 3.56135e+09 7.32891e+10
EOD
set output 'environment_roofline_naive.png'
set title "environment, naive: rays/s that 1080p60 needs against each GPU's limits (1.82 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     6.73575e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.98e+05 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.42321e+09 4.68574e+08 NaN
2016 6.0983e+09 6.69392e+08 NaN
2018 8.11666e+10 9.37149e+08 8e+09
2020 1.19985e+11 1.58981e+09 1.33672e+10
2022 1.96447e+11 1.49944e+09 2.59738e+10
2025 2.62115e+11 2.00818e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.16113e+09 7.03907e+08 NaN
2017 7.79372e+09 1.01246e+09 NaN
2018 1.08408e+11 1.28858e+09 1e+10
2020 1.43419e+11 1.95797e+09 1.59024e+10
2022 3.32839e+11 2.10858e+09 4.40196e+10
2025 4.87904e+11 3.74859e+09 7.32891e+10
EOD
set output 'environment_roofline_bsdf.png'
set title "environment, bsdf: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.25058e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.89e+05 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.2164e+09 4.51797e+08 NaN
2016 5.72987e+09 6.45424e+08 NaN
2018 5.43339e+10 9.03594e+08 8e+09
2020 8.03196e+10 1.53288e+09 1.33672e+10
2022 1.31504e+11 1.44575e+09 2.59738e+10
2025 1.86422e+11 1.93627e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.90974e+09 6.78704e+08 NaN
2017 7.32286e+09 9.76205e+08 NaN
2018 7.25695e+10 1.24244e+09 1e+10
2020 9.60064e+10 1.88787e+09 1.59024e+10
2022 2.22806e+11 2.03309e+09 4.40196e+10
2025 3.47007e+11 3.61438e+09 7.32891e+10
EOD
set output 'environment_roofline_nee.png'
set title "environment, nee: rays/s that 1080p60 needs against each GPU's limits (2.37 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.98701e+10 with lines lc 'black' dt 3 lw 2 title 'need: none, 169 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.04153e+09 4.28588e+08 NaN
2016 5.41835e+09 6.12268e+08 NaN
2018 4.1279e+10 8.57175e+08 8e+09
2020 6.10211e+10 1.45414e+09 1.33672e+10
2022 9.99072e+10 1.37148e+09 2.59738e+10
2025 1.41651e+11 1.8368e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.69717e+09 6.43838e+08 NaN
2017 6.92473e+09 9.26055e+08 NaN
2018 5.51331e+10 1.17862e+09 1e+10
2020 7.29388e+10 1.79088e+09 1.59024e+10
2022 1.69272e+11 1.92864e+09 4.40196e+10
2025 2.63671e+11 3.4287e+09 7.32891e+10
EOD
set output 'environment_roofline_bdpt.png'
set title "environment, bdpt: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.25058e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.89e+05 spp'
