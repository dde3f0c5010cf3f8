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
2014 2.79666e+09 2.82798e+08 NaN
2016 4.98213e+09 4.03997e+08 NaN
2018 6.68774e+10 5.65596e+08 8e+09
2020 1.09488e+11 9.59494e+08 1.33672e+10
2022 1.7926e+11 9.04954e+08 2.59738e+10
2025 2.06988e+11 1.21199e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.39952e+09 4.24828e+08 NaN
2017 6.36724e+09 6.11046e+08 NaN
2018 8.93229e+10 7.77695e+08 1e+10
2020 1.30872e+11 1.18169e+09 1.59024e+10
2022 3.0372e+11 1.27259e+09 4.40196e+10
2025 3.8529e+11 2.26239e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_naive.png'
set title "cornell-spheres, naive: rays/s that 1080p60 needs against each GPU's limits (3.57 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.71119e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 8.35e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.51464e+09 2.7237e+08 NaN
2016 4.47971e+09 3.891e+08 NaN
2018 4.3767e+10 5.4474e+08 8e+09
2020 6.46991e+10 9.24113e+08 1.33672e+10
2022 1.05929e+11 8.71584e+08 2.59738e+10
2025 1.48868e+11 1.1673e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.0567e+09 4.09163e+08 NaN
2017 5.72514e+09 5.88514e+08 NaN
2018 5.84562e+10 7.49018e+08 1e+10
2020 7.73351e+10 1.13812e+09 1.59024e+10
2022 1.79475e+11 1.22567e+09 4.40196e+10
2025 2.77105e+11 2.17896e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bsdf.png'
set title "cornell-spheres, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.58 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.36153e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 5.3e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.6507e+09 2.94446e+08 NaN
2016 4.7221e+09 4.20637e+08 NaN
2018 3.50585e+10 5.88892e+08 8e+09
2020 5.18257e+10 9.99013e+08 1.33672e+10
2022 8.48518e+10 9.42227e+08 2.59738e+10
2025 1.24115e+11 1.26191e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.22209e+09 4.42326e+08 NaN
2017 6.03491e+09 6.36213e+08 NaN
2018 4.68249e+10 8.09726e+08 1e+10
2020 6.19475e+10 1.23036e+09 1.59024e+10
2022 1.43764e+11 1.32501e+09 4.40196e+10
2025 2.31028e+11 2.35557e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_nee.png'
set title "cornell-spheres, nee: rays/s that 1080p60 needs against each GPU's limits (5.68 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.85405e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.87e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.70341e+09 2.96267e+08 NaN
2016 4.816e+09 4.23239e+08 NaN
2018 4.42184e+10 5.92535e+08 8e+09
2020 6.53663e+10 1.00519e+09 1.33672e+10
2022 1.07021e+11 9.48056e+08 2.59738e+10
2025 1.57207e+11 1.26972e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.28616e+09 4.45062e+08 NaN
2017 6.15492e+09 6.40149e+08 NaN
2018 5.9059e+10 8.14735e+08 1e+10
2020 7.81327e+10 1.23797e+09 1.59024e+10
2022 1.81326e+11 1.3332e+09 4.40196e+10
2025 2.92627e+11 2.37014e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bdpt.png'
set title "cornell-spheres, bdpt: rays/s that 1080p60 needs against each GPU's limits (12.01 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     9.28009e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.21e+03 spp'
