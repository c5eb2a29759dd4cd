#!/usr/bin/env bash
# MGPCG with Galerkin coarse levels (--solver mgpcg_galerkin) against the geometric ones (the
# presets' mgpcg), one library, interleaved: usage run.sh ROUNDS [aged|kernels] [CONFIGS], CONFIGS
# from lf8 balanced fast (default: all three); PASSES=1 also counts dispatches.
source scripts/device_env.sh >/dev/null 2>&1
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
cd build-dev
LF="--preset balanced --advection leapfrog --cfl 8 --tolerance 1e-3"
row() { grep -E "^($2) +[0-9]" $1 | tr -s ' ' | cut -d' ' -f1,4-6 | tr '\n' '|'; grep -E "solver:" $1 | sed 's/(mean of the most per step;/(/' | tr -s ' ' | tr '\n' '|'; echo; }
./pf_bench --gpu-timing step --warmup 40 --steps 50 original_24 $LF > /dev/null 2>&1
for r in $(seq 1 $1); do
  for v in geometric galerkin; do
    for cfg in "lf8:$LF" "balanced:--preset balanced" "fast:--preset fast"; do
      name=${cfg%%:*}; args=${cfg#*:}
      case " ${3:-lf8 balanced fast} " in *" $name "*) ;; *) continue;; esac
      for s in original_24 dam_break_1m; do
        G=$([ $v = galerkin ] && echo "--solver mgpcg_galerkin")
        ./pf_bench --gpu-timing step --warmup 20 --steps 100 $s $args $G > $OUT/${v}_${name}_${s}_$r.txt 2>&1
        [ $r = 1 ] && [ "$PASSES" = 1 ] && ./pf_bench --gpu-timing passes --warmup 20 --steps 30 $s $args $G > $OUT/${v}_${name}_${s}_p.txt 2>&1
        echo "r$r $v $name: $(row $OUT/${v}_${name}_${s}_$r.txt $s)"
      done
    done
  done
done
if [ "$2" = aged ]; then
  for v in geometric galerkin; do
    G=$([ $v = galerkin ] && echo "--solver mgpcg_galerkin")
    for cfg in "lf8:$LF" "balanced:--preset balanced"; do
      name=${cfg%%:*}; args=${cfg#*:}
      ./pf_bench --gpu-timing step --warmup 150 --steps 40 dam_break_10m $args $G > $OUT/${v}_${name}_10m.txt 2>&1
      echo "10m aged $v $name: $(row $OUT/${v}_${name}_10m.txt dam_break_10m)"
    done
  done
fi
if [ "$2" = kernels ]; then
  for v in geometric galerkin; do
    G=$([ $v = galerkin ] && echo "--solver mgpcg_galerkin")
    ./pf_bench --gpu-timing kernels --warmup 20 --steps 40 dam_break_1m $LF $G > $OUT/k_${v}_lf8.txt 2>&1
    echo "== $v"; sed -n '/Kernels of/,$p' $OUT/k_${v}_lf8.txt | head -30
  done
fi
cd $OUT && tar czf raw.tgz *.txt && rm -f *.txt
