/* core_xdmf.h: the XDMF companion of a run's HDF5 file, so that ParaView (or VisIt) opens the
 * terrain, the support and the legs' centrelines over time.
 *
 * Owns: cs_xdmfWriteRun, which reads the shapes of a run file's datasets (sim_run.c's layout:
 * /time [N], /support/corners [N,8,3], /legs/<A..H>/centerline [N,K,3], /terrain/corners
 * [nbox*8,3]) and writes an XDMF 3 file that references them, never copies them:
 *   - grid "terrain": one hexahedron per terrain box (static, shown at every time);
 *   - a temporal collection of frames, each a spatial collection of grid "support" (one
 *     hexahedron: the support box) and grids "leg_A" .. "leg_H" (one polyline of K points);
 *     every frame's geometry is a hyperslab of the HDF5 series at that sample;
 *   - attributes (cell data, when the run file has the series): the support's
 *     contact_force_N (Vector, /contact/force), each leg's pressure_MPa (its 12 chambers, II1
 *     Ω1 first, /pressure), foot_force_N (Vector, /contact/foot_force) and stance (1 standing,
 *     0 swinging, /contact/stance).
 * ParaView reads it with its "XDMF Reader" (the XDMF 2 reader): its Xdmf3 readers do not
 * resolve HyperSlab DataItems written this way (ParaView 5.11, tests/tools/test_xdmf.py).
 * The HDF5 file is named by its base name, so the pair can be moved together. Frames are every
 * `stride`-th sample (stride >= 1): ParaView reads the XML whole, and 300-1000 frames keep it
 * at 1-3 MB. Leaf-level: only HDF5 and the C library. */
#ifndef CS_CORE_XDMF_H
#define CS_CORE_XDMF_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The frame stride that keeps a series of n samples at about max_frames frames (>= 1). */
long cs_xdmfStride(long n, long max_frames);

/* Write `xdmf_path` for the run file `h5_path` (closed, complete or cut short: the series'
 * current lengths are used). CS_ERR_IO with the file name when either file fails. */
csStatus cs_xdmfWriteRun(const char* h5_path, const char* xdmf_path, long stride, csError* err);

#ifdef __cplusplus
}
#endif
#endif
