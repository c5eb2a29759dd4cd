#!/usr/bin/env bash
# H100: mg_coarse_cycle.comp (one dispatch for the coarse levels) against main (build-dev/old).
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
[ -e samples ] || ln -s /work/main/samples samples 2>/dev/null
cd build-dev
timeout 120 ./pf_internal_tests --gtest_filter='*SolverLadder*:*CoarseCycle*:*Vcycle*' > $OUT/internal_ladder.txt 2>&1; echo "ladder rc=$?"; grep -E "OK \]|FAILED|SCRATCH" $OUT/internal_ladder.txt | sort | uniq -c | head -20
row() { grep -E "^(original_24|dam_break_1m) +[0-9]" $1 | tr -s ' ' | cut -d' ' -f1,4-6 | tr '\n' '|'; echo; }
./pf_bench --gpu-timing step --warmup 30 --steps 30 original_24 --preset fast > /dev/null 2>&1
for r in 1 2; do
for v in old new new16 new32 new8; do
  L=$PWD; [ $v = old ] && L=$PWD/old
  G=; case $v in new16) G=16;; new32) G=32;; new8) G=8;; esac
  PFX_CYCLE_GROUPS=$G LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH timeout 100 ./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m --preset fast > $OUT/${v}_fast_$r.txt 2>&1
  echo "r$r $v fast: $(row $OUT/${v}_fast_$r.txt) $(grep -m1 SCRATCH $OUT/${v}_fast_$r.txt)"
done
done
for v in old new; do
  L=$PWD; [ $v = old ] && L=$PWD/old
  LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH timeout 100 ./pf_bench --gpu-timing step --warmup 20 --steps 100 original_24 dam_break_1m --preset balanced > $OUT/${v}_balanced.txt 2>&1
  echo "$v balanced: $(row $OUT/${v}_balanced.txt)"
  LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH timeout 100 ./pf_bench --gpu-timing kernels --warmup 20 --steps 30 dam_break_1m --preset fast > $OUT/k_${v}.txt 2>&1
done
sed -n '/Kernels of/,$p' $OUT/k_new.txt | head -20
