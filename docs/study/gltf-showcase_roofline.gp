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
2014 2.11835e+09 2.86973e+08 NaN
2016 3.77374e+09 4.09961e+08 NaN
2018 8.93782e+10 5.73945e+08 8e+09
2020 1.50996e+11 9.73657e+08 1.33672e+10
2022 2.4722e+11 9.18312e+08 2.59738e+10
2025 2.85459e+11 1.22988e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.57499e+09 4.31099e+08 NaN
2017 4.8229e+09 6.20066e+08 NaN
2018 1.19375e+11 7.89175e+08 1e+10
2020 1.80487e+11 1.19914e+09 1.59024e+10
2022 4.18863e+11 1.29138e+09 4.40196e+10
2025 5.31357e+11 2.29578e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_naive.png'
set title "gltf-showcase, naive: rays/s that 1080p60 needs against each GPU's limits (2.07 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.64299e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.05249e+09 2.86973e+08 NaN
2016 3.65643e+09 4.09961e+08 NaN
2018 6.24839e+10 5.73945e+08 8e+09
2020 9.23675e+10 9.73657e+08 1.33672e+10
2022 1.51229e+11 9.18312e+08 2.59738e+10
2025 2.06456e+11 1.22988e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.49494e+09 4.31099e+08 NaN
2017 4.67297e+09 6.20066e+08 NaN
2018 8.34548e+10 7.89175e+08 1e+10
2020 1.10407e+11 1.19914e+09 1.59024e+10
2022 2.56227e+11 1.29138e+09 4.40196e+10
2025 3.843e+11 2.29578e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bsdf.png'
set title "gltf-showcase, bsdf: rays/s that 1080p60 needs against each GPU's limits (2.07 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.64299e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.03e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.04644e+09 2.87985e+08 NaN
2016 3.64565e+09 4.11407e+08 NaN
2018 4.04007e+10 5.75969e+08 8e+09
2020 5.97228e+10 9.77091e+08 1.33672e+10
2022 9.77814e+10 9.21551e+08 2.59738e+10
2025 1.41342e+11 1.23422e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.48758e+09 4.3262e+08 NaN
2017 4.65919e+09 6.22253e+08 NaN
2018 5.39601e+10 7.91958e+08 1e+10
2020 7.13869e+10 1.20336e+09 1.59024e+10
2022 1.65671e+11 1.29593e+09 4.40196e+10
2025 2.63095e+11 2.30388e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_nee.png'
set title "gltf-showcase, nee: rays/s that 1080p60 needs against each GPU's limits (2.67 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     9.12452e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.75e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.31542e+09 3.26205e+08 NaN
2016 4.12483e+09 4.66008e+08 NaN
2018 4.27738e+10 6.52411e+08 8e+09
2020 6.32309e+10 1.10677e+09 1.33672e+10
2022 1.03525e+11 1.04386e+09 2.59738e+10
2025 1.51157e+11 1.39802e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.81455e+09 4.90036e+08 NaN
2017 5.27159e+09 7.04837e+08 NaN
2018 5.71297e+10 8.97065e+08 1e+10
2020 7.55802e+10 1.36307e+09 1.59024e+10
2022 1.75402e+11 1.46792e+09 4.40196e+10
2025 2.81365e+11 2.60964e+09 7.32891e+10
EOD
set output 'gltf-showcase_roofline_bdpt.png'
set title "gltf-showcase, bdpt: rays/s that 1080p60 needs against each GPU's limits (4.66 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.88227e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 670 spp'
