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
2014 2.74167e+09 2.78427e+08 NaN
2016 4.88416e+09 3.97753e+08 NaN
2018 6.70134e+10 5.56854e+08 8e+09
2020 1.0967e+11 9.44664e+08 1.33672e+10
2022 1.79557e+11 8.90967e+08 2.59738e+10
2025 2.07331e+11 1.19326e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.33267e+09 4.18262e+08 NaN
2017 6.24203e+09 6.01602e+08 NaN
2018 8.95045e+10 7.65675e+08 1e+10
2020 1.31089e+11 1.16343e+09 1.59024e+10
2022 3.04223e+11 1.25292e+09 4.40196e+10
2025 3.85928e+11 2.22742e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_naive.png'
set title "cornell-spheres, naive: rays/s that 1080p60 needs against each GPU's limits (3.64 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.60768e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 7.97e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.45607e+09 2.6706e+08 NaN
2016 4.37537e+09 3.81514e+08 NaN
2018 4.38024e+10 5.3412e+08 8e+09
2020 6.47514e+10 9.06096e+08 1.33672e+10
2022 1.06014e+11 8.54591e+08 2.59738e+10
2025 1.49056e+11 1.14454e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.9855e+09 4.01186e+08 NaN
2017 5.59179e+09 5.7704e+08 NaN
2018 5.85034e+10 7.34415e+08 1e+10
2020 7.73976e+10 1.11593e+09 1.59024e+10
2022 1.7962e+11 1.20177e+09 4.40196e+10
2025 2.77455e+11 2.13648e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bsdf.png'
set title "cornell-spheres, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.67 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.12196e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 4.65e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.59867e+09 2.89401e+08 NaN
2016 4.62941e+09 4.1343e+08 NaN
2018 3.49476e+10 5.78802e+08 8e+09
2020 5.16617e+10 9.81895e+08 1.33672e+10
2022 8.45834e+10 9.26082e+08 2.59738e+10
2025 1.23749e+11 1.24029e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.15884e+09 4.34747e+08 NaN
2017 5.91646e+09 6.25312e+08 NaN
2018 4.66768e+10 7.95852e+08 1e+10
2020 6.17515e+10 1.20928e+09 1.59024e+10
2022 1.43309e+11 1.3023e+09 4.40196e+10
2025 2.30347e+11 2.31521e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_nee.png'
set title "cornell-spheres, nee: rays/s that 1080p60 needs against each GPU's limits (5.78 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.38302e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.31e+03 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 2.67618e+09 2.9373e+08 NaN
2016 4.76749e+09 4.19615e+08 NaN
2018 4.41604e+10 5.87461e+08 8e+09
2020 6.52805e+10 9.96585e+08 1.33672e+10
2022 1.06881e+11 9.39937e+08 2.59738e+10
2025 1.57013e+11 1.25884e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.25306e+09 4.41251e+08 NaN
2017 6.09292e+09 6.34667e+08 NaN
2018 5.89815e+10 8.07758e+08 1e+10
2020 7.80301e+10 1.22737e+09 1.59024e+10
2022 1.81088e+11 1.32179e+09 4.40196e+10
2025 2.92266e+11 2.34984e+09 7.32891e+10
EOD
set output 'cornell-spheres_roofline_bdpt.png'
set title "cornell-spheres, bdpt: rays/s that 1080p60 needs against each GPU's limits (12.15 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     5.22096e+12 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.45e+03 spp'
