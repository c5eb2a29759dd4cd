#!/bin/bash
# usage: val.sh NAME CASE SCALE [ENV...]
name=$1; case=$2; scale=$3; shift 3
cd /tmp/wt/build
env "$@" LP_NUM_THREADS=0 ./samples/pf_validation --cells 16 --preset balanced --case $case --advection leapfrog --cfl 8 --tolerance 1e-3 --scale $scale --perturb 1 2 3 4 5 6 7 8 --json /tmp/lft/$name.json > /tmp/lft/$name.log 2>&1
echo done >> /tmp/lft/$name.log
