"""crawlsim.results: a run's HDF5 file as numpy arrays, and the support's heading.

Owns: `RunFile` (every series of docs/reference/output.md "Run HDF5" read into numpy arrays,
the root attributes as text or numbers), `read_run(path)`, and `heading_deg(quat)`, the yaw
of the support about the world's vertical y (docs/reference.md "Units and frames").

Units are the file's: mm, s, MPa, N; positions in the world frame (x crawl, y up, z lateral).
A file that is missing, not HDF5, or lacks a series of the output contract raises
`crawlsim.Error` with one line naming the file and the cause.
"""

import os

import numpy as np

from .errors import Error

LEGS = "ABCDEFGH"

# the series every run file holds (docs/design.md "Output contract (HDF5)"): attribute name on
# RunFile -> (dataset path, expected trailing shape; None = any size)
_SERIES = {
    "t": ("/time", ()),
    "position": ("/support/position", (3,)),
    "orientation": ("/support/orientation", (4,)),
    "pressure": ("/pressure", (96,)),
}
# series a run file holds since issue 36; read when present (older files lack them)
_OPTIONAL = {
    "foot_force": ("/contact/foot_force", (8, 3)),
    "stance": ("/contact/stance", (8,)),
    "corners": ("/support/corners", (8, 3)),
    "contact_force": ("/contact/force", (3,)),
}


def _text(v):
    """An attribute value as Python text or number: fixed-length strings come back from h5py
    as bytes (docs/reference/output.md), numbers as numpy scalars or 1-element arrays."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray) and v.size == 1:
        v = v.reshape(-1)[0]
    if isinstance(v, np.generic):
        return v.item()
    return v


def heading_deg(quat):
    """Heading of the support (deg) from its orientation quaternion(s) (w, x, y, z), shape (4)
    or (N, 4): the angle of the support's x axis projected on the ground (x-z) plane, measured
    from world +x, positive counter-clockwise seen from above (+y), i.e. towards -z, the side of
    legs A-D. Unwrapped along N so a turn past 180 deg stays continuous."""
    q = np.asarray(quat, dtype=float)
    w, x, y, z = (q[..., k] for k in range(4))
    # first column of the rotation matrix: the support's x axis in the world frame
    ex_x = 1.0 - 2.0 * (y * y + z * z)
    ex_z = 2.0 * (x * z - w * y)
    psi = np.arctan2(-ex_z, ex_x)
    if psi.ndim == 1:
        psi = np.unwrap(psi)
    return np.degrees(psi)


class RunFile:
    """The contents of one run file. Arrays (float64 unless said):
    t [N] s; position [N,3] mm (the support's displacement from t = 0, world); orientation
    [N,4] (w, x, y, z); pressure [N,96] MPa (label L is column L - 1); centerline [8,N,K,3] mm
    (legs A..H, world, hip to foot); foot_force [N,8,3] N and stance [N,8] (0/1) when the file
    has them, else None; attrs: dict of the root attributes (text or numbers); path."""

    def __init__(self, path):
        import h5py  # imported here: only reading files needs it

        self.path = os.fspath(path)
        if not os.path.isfile(self.path):
            raise Error(f"{self.path}: no such file")
        try:
            f = h5py.File(self.path, "r")
        except OSError as e:
            raise Error(f"{self.path}: not a readable HDF5 file ({str(e).splitlines()[0]})") from None
        with f:
            self.attrs = {k: _text(v) for k, v in f.attrs.items()}
            for name, (ds, tail) in _SERIES.items():
                setattr(self, name, self._read(f, ds, tail))
            for name, (ds, tail) in _OPTIONAL.items():
                setattr(self, name, self._read(f, ds, tail) if ds in f else None)
            n = self.t.shape[0]
            legs = [self._read(f, f"/legs/{leg}/centerline", (None, 3)) for leg in LEGS]
            self.centerline = np.stack(legs) if legs else np.zeros((8, n, 0, 3))
        for name in list(_SERIES) + list(_OPTIONAL):
            a = getattr(self, name)
            if a is not None and a.shape[0] != n:
                raise Error(f"{self.path}: {name} has {a.shape[0]} rows, /time has {n}")

    def _read(self, f, ds, tail):
        if ds not in f:
            raise Error(f"{self.path}: missing dataset {ds}")
        try:
            a = np.asarray(f[ds][()], dtype=float)
        except (TypeError, ValueError, AttributeError) as e:
            raise Error(f"{self.path}: {ds} is not a numeric dataset ({e})") from None
        ok = a.ndim == len(tail) + 1 and all(s is None or a.shape[1 + i] == s
                                             for i, s in enumerate(tail))
        if not ok:
            want = ",".join(["N"] + ["K" if s is None else str(s) for s in tail])
            raise Error(f"{self.path}: {ds} has shape {list(a.shape)}, expected [{want}]")
        return a

    @property
    def heading(self):
        """[N] deg: heading_deg of every sample's orientation."""
        return heading_deg(self.orientation)

    @property
    def status(self):
        """The run's status attribute ("ok", "interrupted at t = ... s" or the error)."""
        return str(self.attrs.get("status", ""))

    def __repr__(self):
        n = self.t.shape[0]
        end = f"{self.t[-1]:.3g} s" if n else "no samples"
        return (f"RunFile({self.path!r}: {n} samples to {end}, legs {self.attrs.get('leg_model')}, "
                f"status {self.status!r})")


def read_run(path):
    """Read a run file (`crawlsim run --out`, `crawlsim.run(out=...)`) into a RunFile."""
    return RunFile(path)


def tilt_deg(quat):
    """Angle (deg) between the support's up axis and world up, from quaternion(s) (w, x, y, z):
    the `tilt` of `crawlsim run`'s verdict line (tools/cmd_run.c)."""
    q = np.asarray(quat, dtype=float)
    c = 1.0 - 2.0 * (q[..., 1] ** 2 + q[..., 3] ** 2)
    return np.degrees(np.arccos(np.minimum(1.0, c)))


__all__ = ["RunFile", "read_run", "heading_deg", "tilt_deg", "LEGS"]
