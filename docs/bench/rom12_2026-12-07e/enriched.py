#!/usr/bin/python3
"""Run one of rom11's screens (fibre_free_projection.py, fibre_consistency.py,
pressure_residual.py, rom11_energy.py, ...) on the basis' V enriched by the first K columns of
/D of E.h5 (rom11_iso_diag.py Model's --enrich: M-orthonormalised against V, twice):
    ENRICH=E.h5:K enriched.py SCRIPT.py ARGS...
Without ENRICH the script runs unchanged. (rom12: the screens take the enrichment without
editing each one; rom11_iso_diag.Model is the class every one of them builds.)"""
import os
import runpy
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "rom"))
import rom11_iso_diag  # noqa: E402

spec = os.environ.get("ENRICH")
if spec:
    path, k = spec.rsplit(":", 1)
    orig = rom11_iso_diag.Model.__init__

    def init(self, snapdir, basis, legfile, enrich=None, k_=0, **kw):
        orig(self, snapdir, basis, legfile, path, int(k))
        print(f"enriched.py: V enriched by the first {k} columns of {path}: n = "
              f"{self.n0} + {self.V.shape[1] - self.n0}")

    rom11_iso_diag.Model.__init__ = init
script = sys.argv[1]
sys.path.insert(0, os.path.dirname(os.path.abspath(script)))
sys.argv = sys.argv[1:]
runpy.run_path(script, run_name="__main__")
