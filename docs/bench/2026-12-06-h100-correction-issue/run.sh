#!/usr/bin/env bash
# H200: leapfrog at CFL 8 with its gravity-time limits, and the correction's issued iterations
# before (build-dev: main at 29d439c) and after (build-dev/after: main at 6dc0a1f).
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
LF="--preset balanced --advection leapfrog --cfl 8"
row() { grep -E "^($2) +[0-9]" $1 | tr -s ' ' | cut -d' ' -f1,4-6 | tr '\n' '|'; for s in ${2//|/ }; do echo -n " $s disp $(grep -E "^$s +total " ${1%.txt}_p.txt 2>/dev/null | tr -s ' ' | cut -d' ' -f4)"; done; echo; }
./pf_bench --gpu-timing step --warmup 40 --steps 50 original_24 $LF > /dev/null 2>&1
for r in 1 2; do
  for v in before after; do
    if [ $v = after ]; then L="$PWD/after"; else L="$PWD"; fi
    B=$([ $v = after ] && echo after/pf_bench || echo ./pf_bench)
    for cfg in "lf8:$LF --tolerance 1e-3" "balanced:--preset balanced" "fast:--preset fast"; do
      name=${cfg%%:*}; args=${cfg#*:}
      LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH $B --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m $args > $OUT/${v}_${name}_$r.txt 2>&1
      [ $r = 1 ] && LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH $B --gpu-timing passes --warmup 20 --steps 30 original_24 dam_break_1m $args > $OUT/${v}_${name}_${r}_p.txt 2>&1
      echo "r$r $v $name: $(row $OUT/${v}_${name}_$r.txt 'original_24|dam_break_1m')"
    done
  done
done
for v in before after; do
  if [ $v = after ]; then L="$PWD/after"; B=after/pf_bench; else L="$PWD"; B=./pf_bench; fi
  LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH $B --gpu-timing step --warmup 150 --steps 40 dam_break_10m $LF --tolerance 1e-3 > $OUT/${v}_lf10.txt 2>&1
  echo "10m aged lf8 $v: $(grep -E '^dam_break_10m +[0-9]' $OUT/${v}_lf10.txt | tr -s ' ' | cut -d' ' -f1,4-6)"
done
LD_LIBRARY_PATH=$PWD/after:$LD_LIBRARY_PATH after/pf_bench --gpu-timing kernels --warmup 20 --steps 60 dam_break_1m $LF --tolerance 1e-3 > $OUT/k_after_lf8.txt 2>&1
sed -n '/Kernels of/,$p' $OUT/k_after_lf8.txt | head -24
