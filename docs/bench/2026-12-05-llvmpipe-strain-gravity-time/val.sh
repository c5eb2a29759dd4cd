#!/bin/bash
# usage: val.sh NAME SCALE [ENV...]
name=$1; scale=$2; shift 2
cd /tmp/wt/build
env "$@" LP_NUM_THREADS=0 ./samples/pf_validation --cells 16 --preset balanced --case martin_moyce_2 --advection leapfrog --cfl 8 --tolerance 1e-3 --scale $scale --perturb 1 2 3 4 5 6 7 8 --json /tmp/val_$name.json > /tmp/val_$name.log 2>&1
echo done >> /tmp/val_$name.log
