#!/usr/bin/env bash
# H100: mg_coarse_cycle.comp with 256-invocation workgroups, several workgroup counts.
source scripts/device_env.sh >/dev/null 2>&1
cd build-dev
row() { grep -E "^(original_24|dam_break_1m) +[0-9]" $1 | tr -s ' ' | cut -d' ' -f1,4-6 | tr '\n' '|'; echo; }
./pf_bench --gpu-timing step --warmup 30 --steps 30 original_24 --preset fast > /dev/null 2>&1
for v in old new new32 new64 new128 new16; do
  L=$PWD; [ $v = old ] && L=$PWD/old
  G=; case $v in new16) G=16;; new32) G=32;; new64) G=64;; new128) G=128;; esac
  PFX_CYCLE_GROUPS=$G LD_LIBRARY_PATH=$L:$LD_LIBRARY_PATH timeout 100 ./pf_bench --gpu-timing step --warmup 20 --steps 60 dam_break_1m --preset fast > $OUT/w256_${v}_fast.txt 2>&1
  echo "$v fast: $(row $OUT/w256_${v}_fast.txt) $(grep SCRATCH $OUT/w256_${v}_fast.txt | tail -1)"
done
PFX_CYCLE_GROUPS=64 timeout 100 ./pf_bench --gpu-timing kernels --warmup 20 --steps 30 dam_break_1m --preset fast > $OUT/w256_k64.txt 2>&1
grep -E "mg_coarse_cycle" $OUT/w256_k64.txt | head
