#!/bin/sh
# the default flat road, earth, then the obstacle on the new defaults (one core, sequential)
B=build/tools/crawlsim  # from the repository root
[ -f fr_default.h5 ] || /usr/bin/time -f "cpu %U s wall %e s" $B run --scene flat-road --out fr_default.h5 > fr_default.log 2>&1
[ -f fr_earth.h5 ] || /usr/bin/time -f "cpu %U s wall %e s" $B run --scene flat-road --conditions earth --out fr_earth.h5 > fr_earth.log 2>&1
# [ -f obstacle.h5 ] || /usr/bin/time -f "cpu %U s wall %e s" $B run --scene obstacle --out obstacle.h5 > obstacle.log 2>&1
