#!/usr/bin/python3
"""A copy of an every-element leg file with another mixed fibre basis (rom11): the chamber forms
(the leg file's n^3 set-up) depend on V only, so a fibre basis is checked without remaking them.
/Qf replaced by the first K columns of SRC.h5's /Qf (K = 0: every column), attribute mf set to
match; everything else copied bit for bit. robot/rom/robot_rom_file.c reads /Qf's own width.
Usage: swap_qf.py LEG.h5 SRC.h5 K OUT.h5"""
import os
import sys

import h5py

leg, srcf, k, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
with h5py.File(srcf, "r") as s:
    Q = s["Qf"][:, :k] if k > 0 else s["Qf"][...]
with h5py.File(leg, "r") as src, h5py.File(out + ".tmp", "w") as dst:
    if src["Qf"].shape[0] != Q.shape[0]:
        sys.exit(f"swap_qf: {srcf}: {Q.shape[0]} fibres, {leg} {src['Qf'].shape[0]}")
    for key, v in src.attrs.items():
        dst.attrs[key] = v
    dst.attrs["mf"] = float(Q.shape[1])
    for key in src:
        if key != "Qf":
            src.copy(key, dst)
    dst.create_dataset("Qf", data=Q)
os.replace(out + ".tmp", out)
print(f"swap_qf: {out}: mf = {Q.shape[1]}")
