#!/bin/sh
B=build/tools/crawlsim  # from the repository root
[ -f fr_paper.h5 ] || /usr/bin/time -f "cpu %U s wall %e s" $B run --scene flat-road --gait gaits/flat_road_paper.csv --conditions paper --out fr_paper.h5 > fr_paper.log 2>&1
[ -f obstacle.h5 ] || /usr/bin/time -f "cpu %U s wall %e s" $B run --scene obstacle --out obstacle.h5 > obstacle.log 2>&1
