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
2014 2.12781e+09 2.88372e+08 NaN
2016 3.79061e+09 4.11961e+08 NaN
2018 8.92409e+10 5.76745e+08 8e+09
2020 1.50817e+11 9.78406e+08 1.33672e+10
2022 2.46926e+11 9.22792e+08 2.59738e+10
2025 2.85121e+11 1.23588e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.58649e+09 4.33202e+08 NaN
2017 4.84445e+09 6.2309e+08 NaN
2018 1.19192e+11 7.93024e+08 1e+10
2020 1.80273e+11 1.20498e+09 1.59024e+10
2022 4.18366e+11 1.29768e+09 4.40196e+10
2025 5.30727e+11 2.30698e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_naive.png'
set title "gltf-showcase, naive: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.62997e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.06133e+09 2.88372e+08 NaN
2016 3.67217e+09 4.11961e+08 NaN
2018 6.2439e+10 5.76745e+08 8e+09
2020 9.23011e+10 9.78406e+08 1.33672e+10
2022 1.5112e+11 9.22792e+08 2.59738e+10
2025 2.06238e+11 1.23588e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.50568e+09 4.33202e+08 NaN
2017 4.69309e+09 6.2309e+08 NaN
2018 8.33949e+10 7.93024e+08 1e+10
2020 1.10328e+11 1.20498e+09 1.59024e+10
2022 2.56043e+11 1.29768e+09 4.40196e+10
2025 3.83894e+11 2.30698e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bsdf.png'
set title "gltf-showcase, bsdf: rays/s that 1080p60 needs against each GPU's limits (2.05 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.62997e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.05382e+09 2.89173e+08 NaN
2016 3.6588e+09 4.13104e+08 NaN
2018 4.04159e+10 5.78345e+08 8e+09
2020 5.97453e+10 9.81122e+08 1.33672e+10
2022 9.78182e+10 9.25353e+08 2.59738e+10
2025 1.41371e+11 1.23931e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.49655e+09 4.34405e+08 NaN
2017 4.676e+09 6.2482e+08 NaN
2018 5.39804e+10 7.95225e+08 1e+10
2020 7.14138e+10 1.20833e+09 1.59024e+10
2022 1.65733e+11 1.30128e+09 4.40196e+10
2025 2.6315e+11 2.31338e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_nee.png'
set title "gltf-showcase, nee: rays/s that 1080p60 needs against each GPU's limits (2.65 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     9.14554e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.77e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.32258e+09 3.27328e+08 NaN
2016 4.13757e+09 4.67611e+08 NaN
2018 4.28085e+10 6.54656e+08 8e+09
2020 6.32822e+10 1.11058e+09 1.33672e+10
2022 1.03609e+11 1.04745e+09 2.59738e+10
2025 1.51269e+11 1.40283e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.82324e+09 4.91723e+08 NaN
2017 5.28788e+09 7.07262e+08 NaN
2018 5.7176e+10 9.00152e+08 1e+10
2020 7.56415e+10 1.36776e+09 1.59024e+10
2022 1.75544e+11 1.47298e+09 4.40196e+10
2025 2.81573e+11 2.61862e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bdpt.png'
set title "gltf-showcase, bdpt: rays/s that 1080p60 needs against each GPU's limits (4.64 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.33763e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 752 spp'
