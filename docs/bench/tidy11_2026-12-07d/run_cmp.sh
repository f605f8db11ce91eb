#!/bin/sh
# the same rom commands on the base build and on the branch build; outputs in base/ and new/
for b in base new; do
  exe=/tmp/tidy11_base/tools/crawlsim; [ $b = new ] && exe=/work/wt-tidy11/build/tools/crawlsim
  mkdir -p $b && cd $b
  $exe rom check --snapshots ../snaps --basis ../basis.h5 --ray O12 > check.txt 2> check.err; echo "check rc=$?" >> rc.txt
  $exe rom ecsw-matrix --basis ../basis.h5 --out ecsw.h5 > ecsw.txt 2> ecsw.err; echo "ecsw rc=$?" >> rc.txt
  $exe bend --model rom --rom-basis ../basis.h5 --p-max 0.1 --out bend.h5 > bend.txt 2> bend.err; echo "bend rc=$?" >> rc.txt
  cd ..
done
echo done
