/* study_sched.h: who runs which case of a study: sequentially in one process, or one case per
 * MPI rank under mpirun (OpenMPI), handed out dynamically by rank 0 or split statically.
 *
 * Owns: the MPI life cycle of a study (csxStudyMpi: initialised only when the process was
 * started by an MPI launcher, so `crawlsim study` without mpirun never touches MPI), the
 * broadcast of rank 0's decisions, and the schedulers. Library part of the study layer
 * (cs_study); MPI code is compiled only with CS_WITH_MPI (CS_HAVE_MPI), otherwise every process
 * is rank 0 of 1.
 *
 * Dynamic schedule (default): rank 0 runs cases itself and, in a second thread, hands the next
 * pending case (file order) to any rank that asks; a rank asks again when its case is done, so
 * cases of very different cost (a 1 s analytic bend, a 40 min FE sweep) fill the ranks. The
 * thread is the only one that calls MPI while cases run (MPI_THREAD_SERIALIZED is enough); it
 * polls with MPI_Iprobe every 10 ms instead of blocking in MPI_Recv, which in OpenMPI spins a
 * core that the FE needs. Static schedule: pending case k runs on rank k mod size, no thread.
 * Either way every rank writes its own case files (study_case.h) into the one case directory
 * (a shared file system when the ranks run on several machines), and rank 0 merges them at the
 * end. A killed rank stops the whole mpirun job (OpenMPI's default); the finished cases stay
 * finished and a rerun with --resume computes only the rest. */
#ifndef CS_TOOLS_STUDY_SCHED_H
#define CS_TOOLS_STUDY_SCHED_H

#include "core_status.h"
#include "study_case.h"
#include "study_file.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum csxSchedule_ {
  CSX_SCHEDULE_DYNAMIC = 0,
  CSX_SCHEDULE_STATIC = 1
} csxSchedule;

/* This process's place in the study's MPI job. */
typedef struct csxStudyMpi_ {
  int rank, size;    /* 0 and 1 without MPI */
  int initialised;   /* 1 if MPI is in use (initialised by the study or, in crawlsim-mpi, by
                      * the program before it) */
  int owner;         /* 1 if the study called MPI_Init_thread (and must finalize) */
  int threads_ok;    /* 1 if MPI gave MPI_THREAD_SERIALIZED or more (dynamic schedule) */
} csxStudyMpi;

/* 1 if this build has MPI (CS_WITH_MPI). */
int csx_studyHaveMpi(void);

/* 1 if an MPI launcher (mpirun/mpiexec: OpenMPI, MPICH, PMIx) started this process. */
int csx_studyUnderLauncher(void);

/* Initialise MPI when started by a launcher (and the build has MPI); otherwise rank 0 of 1. */
csStatus csx_studyMpiInit(int* argc, char*** argv, csxStudyMpi* mpi, csError* err);

/* Finalise MPI if it was initialised; waits, without spinning, until every rank gets here. */
void csx_studyMpiFinalize(csxStudyMpi* mpi);

/* Broadcast n ints from rank 0 to every rank (a no-op on one rank). */
void csx_studyMpiBcastInts(const csxStudyMpi* mpi, int* v, int n);

/* Called (on rank 0 only for the dynamic schedule, on the rank that ran it for the static one)
 * when case `index` has finished: `done` of `total` cases of this invocation. */
typedef void (*csxStudyProgress)(void* user, int done, int total, int index,
                                 const csxCaseResult* res);

/* Run the pending cases (indices into s->cases) on every rank of mpi with `kind`; every rank
 * calls this with the same list. Returns CS_OK when every case ran (whatever its outcome), or
 * the first error of this rank (a case file that could not be written). On rank 0 *nfailed
 * gets the count of cases that failed; other ranks get their own count. */
csStatus csx_studyRunPending(const csxStudy* s, const int* pending, int npending, const char* dir,
                             const csxStudyCommands* cmd, csxSchedule kind,
                             const csxStudyMpi* mpi, csxStudyProgress progress, void* user,
                             int* nfailed, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_TOOLS_STUDY_SCHED_H */
