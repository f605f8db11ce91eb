#!/usr/bin/python3
"""cmpdump.py A.bin B.bin: two final states written by bench_strain_step / bench_strain_robot
(STRAIN_DUMP=FILE: raw doubles): byte-identical or not, the largest |d| and |d| / (1 + |a|)."""
import struct
import sys


def rd(p):
    b = open(p, "rb").read()
    return b, struct.unpack("%dd" % (len(b) // 8), b)


ba, a = rd(sys.argv[1])
bb, b = rd(sys.argv[2])
if len(a) != len(b):
    sys.exit("sizes differ")
d = [abs(x - y) for x, y in zip(a, b)]
r = [abs(x - y) / (1 + abs(x)) for x, y in zip(a, b)]
print("%s n %d max|d| %.3g max|d|/(1+|a|) %.3g entries differing %d"
      % ("identical" if ba == bb else "differ", len(a), max(d), max(r),
         sum(1 for x, y in zip(a, b) if x != y)))
