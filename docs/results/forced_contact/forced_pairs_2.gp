set terminal svg size 1000,420 dynamic font 'sans,11'
set output 'forced_pairs_2.svg'
set datafile missing '?'
set grid
set key outside right
set xlabel 'time [s]'
set ylabel 'intersecting triangle pairs (mean over runs)'
set title 'hold 3 s: grips take hold at 1.5 s, let go at 5.3 s'
set arrow from 1.5,graph 0 to 1.5,graph 1 nohead dt 2
set arrow from 5.3,graph 0 to 5.3,graph 1 nohead dt 2
plot 'forced_pairs_2.dat' using 1:2 with lines lw 2 title 'none', 'forced_pairs_2.dat' using 1:3 with lines lw 2 title 'gia', 'forced_pairs_2.dat' using 1:4 with lines lw 2 title 'edge1', 'forced_pairs_2.dat' using 1:5 with lines lw 2 title 'edge2', 'forced_pairs_2.dat' using 1:6 with lines lw 2 title 'edge3', 'forced_pairs_2.dat' using 1:7 with lines lw 2 title 'gia+edge3', 'forced_pairs_2.dat' using 1:8 with lines lw 2 title 'impulse'
