#!/usr/bin/env bash
# Leapfrog at a projection CFL of 8 against the pressure tolerance: frame times and pf_validation.
source scripts/device_env.sh
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
LF="--preset balanced --advection leapfrog --cfl 8"
s=$SECONDS
for tol in 1e-3 3e-3 1e-2 3e-2; do
  ./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m $LF --tolerance $tol > $OUT/t_$tol.txt 2>&1
  echo "tol $tol: $(grep -E '^(original_24|dam_break_1m) ' $OUT/t_$tol.txt | tr -s ' ' | tr '\n' '|')"
  grep -E "solver:" $OUT/t_$tol.txt | head -2
done
./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m --preset balanced > $OUT/t_bal.txt 2>&1
echo "balanced: $(grep -E '^(original_24|dam_break_1m) ' $OUT/t_bal.txt | tr -s ' ' | tr '\n' '|')"
./pf_bench --gpu-timing kernels --warmup 20 --steps 60 dam_break_1m $LF --tolerance 1e-2 > $OUT/k_1e-2.txt 2>&1
for tol in 1e-3 1e-2; do
  ./pf_bench --gpu-timing step --warmup 10 --steps 40 dam_break_10m $LF --tolerance $tol > $OUT/t10_$tol.txt 2>&1
  echo "10m tol $tol: $(grep -E '^dam_break_10m ' $OUT/t10_$tol.txt | tr -s ' ')"
done
echo "timings $((SECONDS-s)) s"
s=$SECONDS
rm -f jobs.txt
for cfg in "bal|--preset balanced" "lf_1e-3|$LF --tolerance 1e-3" "lf_3e-3|$LF --tolerance 3e-3" "lf_1e-2|$LF --tolerance 1e-2"; do
  tag=${cfg%%|*}; args=${cfg#*|}
  for c in martin_moyce_2 martin_moyce_1; do
    echo "./pf_validation --cells 16 $args --case $c > $OUT/v_${tag}_${c}_16.txt 2>&1" >> jobs.txt
    echo "./pf_validation --cells 16 $args --case $c --perturb 1 --perturb 2 --perturb 3 --perturb 4 --perturb 5 --perturb 6 --perturb 7 --perturb 8 > $OUT/v_${tag}_${c}_16p.txt 2>&1" >> jobs.txt
    echo "./pf_validation --cells 32 $args --case $c > $OUT/v_${tag}_${c}_32.txt 2>&1" >> jobs.txt
    echo "./pf_validation --cells 32 $args --case $c --perturb 1 --perturb 2 --perturb 3 --perturb 4 > $OUT/v_${tag}_${c}_32p.txt 2>&1" >> jobs.txt
  done
  echo "./pf_validation --cells 16 $args --case marin_obstacle > $OUT/v_${tag}_marin_16.txt 2>&1" >> jobs.txt
done
xargs -P 10 -I{} bash -c "{}" < jobs.txt
echo "validation $((SECONDS-s)) s"
