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
2014 2.12775e+09 2.88347e+08 NaN
2016 3.79049e+09 4.11924e+08 NaN
2018 8.92226e+10 5.76694e+08 8e+09
2020 1.50789e+11 9.7832e+08 1.33672e+10
2022 2.4688e+11 9.2271e+08 2.59738e+10
2025 2.85067e+11 1.23577e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.58641e+09 4.33164e+08 NaN
2017 4.8443e+09 6.23035e+08 NaN
2018 1.19168e+11 7.92954e+08 1e+10
2020 1.80239e+11 1.20488e+09 1.59024e+10
2022 4.18287e+11 1.29756e+09 4.40196e+10
2025 5.30627e+11 2.30678e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_naive.png'
set title "gltf-showcase, naive: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.63558e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.06126e+09 2.88347e+08 NaN
2016 3.67204e+09 4.11924e+08 NaN
2018 6.24286e+10 5.76694e+08 8e+09
2020 9.22858e+10 9.7832e+08 1.33672e+10
2022 1.51095e+11 9.2271e+08 2.59738e+10
2025 2.06201e+11 1.23577e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.50559e+09 4.33164e+08 NaN
2017 4.69293e+09 6.23035e+08 NaN
2018 8.3381e+10 7.92954e+08 1e+10
2020 1.1031e+11 1.20488e+09 1.59024e+10
2022 2.56e+11 1.29756e+09 4.40196e+10
2025 3.83824e+11 2.30678e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bsdf.png'
set title "gltf-showcase, bsdf: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.63558e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.0541e+09 2.89203e+08 NaN
2016 3.65928e+09 4.13147e+08 NaN
2018 4.04302e+10 5.78405e+08 8e+09
2020 5.97664e+10 9.81224e+08 1.33672e+10
2022 9.78528e+10 9.25449e+08 2.59738e+10
2025 1.41419e+11 1.23944e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.49688e+09 4.3445e+08 NaN
2017 4.67662e+09 6.24884e+08 NaN
2018 5.39994e+10 7.95308e+08 1e+10
2020 7.1439e+10 1.20845e+09 1.59024e+10
2022 1.65792e+11 1.30141e+09 4.40196e+10
2025 2.63239e+11 2.31362e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_nee.png'
set title "gltf-showcase, nee: rays/s that 1080p60 needs against each GPU's limits (2.65 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     8.91321e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.7e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.32233e+09 3.27291e+08 NaN
2016 4.13713e+09 4.67558e+08 NaN
2018 4.27999e+10 6.54581e+08 8e+09
2020 6.32694e+10 1.11045e+09 1.33672e+10
2022 1.03588e+11 1.04733e+09 2.59738e+10
2025 1.51238e+11 1.40267e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.82294e+09 4.91666e+08 NaN
2017 5.28731e+09 7.07181e+08 NaN
2018 5.71645e+10 9.00049e+08 1e+10
2020 7.56262e+10 1.36761e+09 1.59024e+10
2022 1.75509e+11 1.47281e+09 4.40196e+10
2025 2.81517e+11 2.61832e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bdpt.png'
set title "gltf-showcase, bdpt: rays/s that 1080p60 needs against each GPU's limits (4.64 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.09019e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 709 spp'
