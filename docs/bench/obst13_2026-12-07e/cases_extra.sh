#!/bin/sh
# obst13: run.sh's set plus the noise cases: CASE...; NAME one of run.sh's or
# r05half (--ramp 0.5 --step-tol 1.25e-4), r05tau+ / r05tau- (--ramp 0.5 --tau 0.021 / 0.019),
# nomtau+ / nomtau- (--tau 0.021 / 0.019), m25half (--support-mass 0.025 --step-tol 1.25e-4),
# m25tau+ / m25tau- (--support-mass 0.025 --tau 0.021 / 0.019),
# m75tau+ / m75tau- (--support-mass 0.075 --tau 0.021 / 0.019): each through run.sh's EXTRA
cd "$(dirname "$0")"
for n in "$@"; do
  case $n in
    r05half) EXTRA="--step-tol 1.25e-4" c=ramp0.5 ;;
    r05tau+) EXTRA="--tau 0.021" c=ramp0.5 ;;
    r05tau-) EXTRA="--tau 0.019" c=ramp0.5 ;;
    nomtau+) EXTRA="--tau 0.021" c=nominal ;;
    nomtau-) EXTRA="--tau 0.019" c=nominal ;;
    m25half) EXTRA="--step-tol 1.25e-4" c=m25g ;;
    m25tau+) EXTRA="--tau 0.021" c=m25g ;;
    m25tau-) EXTRA="--tau 0.019" c=m25g ;;
    m75tau+) EXTRA="--tau 0.021" c=m75g ;;
    m75tau-) EXTRA="--tau 0.019" c=m75g ;;
    *) EXTRA= c=$n ;;
  esac
  # run.sh names its files GAIT_CASE: the noise case's name goes into the gait's prefix
  if [ -n "$EXTRA" ]; then
    EXTRA="$EXTRA" GAIT=${GAIT:-} NOISE=$n sh ./run.sh "$c"
  else
    sh ./run.sh "$c"
  fi
done
