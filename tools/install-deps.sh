#!/usr/bin/env bash
# Install crawlsim's build and run dependencies from Debian 12 packages.
# Idempotent: packages already present are skipped; re-running costs about a second.
# Why each package is needed is listed in README.md ("Dependencies").
set -euo pipefail

PKGS=(
  build-essential cmake pkg-config          # C17 compiler and build
  libode-dev libccd-dev                     # rigid support, terrain, contacts (ODE uses libccd)
  libsundials-dev                           # CVODE: chamber-pressure dynamics, later the leg states
  libhdf5-dev                               # output files (serial HDF5 + HL)
  gmsh                                      # FE mesher, run as a separate program (GPL stays out of our binaries)
  python3-matplotlib python3-h5py           # plots, run with Debian's /usr/bin/python3
  python3-pytest                            # tests of the Python package (tests/python), run with /usr/bin/python3
  python3-scipy                             # tools/gait_search.py: scipy.optimize's Nelder-Mead over simulations
  libmumps-seq-dev libopenblas0-openmp      # fem: sequential MUMPS sparse LU + fast BLAS (fem/README.md)
  libsuitesparse-dev                        # fem: KLU fallback solver (LGPL)
  libopenmpi-dev openmpi-bin                # crawlsim study under mpirun (CS_WITH_MPI; already pulled in by libsundials-dev)
  libmumps-dev                              # fem: MPI-parallel MUMPS on OpenMPI for crawlsim-mpi (issue 38; optional: without it no crawlsim-mpi)
  clang-14 libclang-rt-14-dev               # fuzzing: libFuzzer + ASan/UBSan runtimes (tests/fuzz)
  libomp-14-dev                             # fuzzing: clang-14's OpenMP, which SUNDIALS' CMake config asks for (OpenMP_C)
  llvm-14                                   # fuzzing: llvm-cov/llvm-profdata, the long run's coverage
)

missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
