source scripts/device_env.sh
B=build-dev/pf_bench
for cfg in "fast" "balanced --max-substeps 1" "balanced"; do
  for scene in dam_break_1m original_24; do
    f=$OUT/$(echo "$cfg $scene" | tr ' -' '__').txt
    timeout 200 $B --warmup 20 --steps 40 --gpu-timing off --preset $cfg $scene > $f 2>&1
    echo "== $cfg $scene: correction iterations (count x iterations), last 40 frames"; grep CORRECTION $f | tail -40 | awk '{print $3}' | sort -n | uniq -c | tr '\n' ' '; echo; grep "solver:" $f
  done
done
