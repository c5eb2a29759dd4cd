#!/usr/bin/env bash
# Before (old/: the library at 45a68d7) and after (1bcfb13): the correction's issue follows its need.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
mkdir -p $OUT/r
LF="--preset balanced --advection leapfrog --cfl 8"
./pf_bench --gpu-timing step --warmup 40 --steps 50 original_24 $LF > /dev/null 2>&1
row() { echo "$(grep -E '^(original_24|dam_break_1m|dam_break_10m) +[0-9]' $1 | tr -s ' ' | cut -d' ' -f1,4,6 | tr '\n' '|') $(grep -E 'solver:' $1 | cut -c3-40 | tr '\n' '|')"; }
for r in 1 2 3; do
  for lib in old new; do
    if [ $lib = old ]; then L="$PWD/old:$LD_LIBRARY_PATH"; else L="$LD_LIBRARY_PATH"; fi
    for cfg in "lf_1e-3|$LF --tolerance 1e-3" "lf_1e-2|$LF --tolerance 1e-2" "bal|--preset balanced"; do
      tag=${cfg%%|*}; args=${cfg#*|}
      LD_LIBRARY_PATH=$L ./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m $args > $OUT/r/${tag}_${lib}_$r.txt 2>&1
      echo "r$r $lib $tag: $(row $OUT/r/${tag}_${lib}_$r.txt)"
    done
  done
done
for lib in old new; do
  if [ $lib = old ]; then L="$PWD/old:$LD_LIBRARY_PATH"; else L="$LD_LIBRARY_PATH"; fi
  LD_LIBRARY_PATH=$L ./pf_bench --gpu-timing step --warmup 10 --steps 40 dam_break_10m $LF --tolerance 1e-2 > $OUT/r/lf10_1e-2_$lib.txt 2>&1
  echo "$lib 10m lf_1e-2: $(row $OUT/r/lf10_1e-2_$lib.txt)"
  LD_LIBRARY_PATH=$L ./pf_bench --gpu-timing kernels --warmup 20 --steps 60 dam_break_1m $LF --tolerance 1e-3 > $OUT/r/k_lf_1e-3_$lib.txt 2>&1
  echo "$lib kernels lf_1e-3: $(grep -E 'cg_matvec_stored_pair' $OUT/r/k_lf_1e-3_$lib.txt | tr -s ' ')"
done
cd $OUT && tar czf r.tgz r && rm -rf r
