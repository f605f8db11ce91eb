/* study_sched.c: sequential, dynamic (rank 0 hands out cases) and static schedules of a study
 * (see study_sched.h). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef CS_HAVE_MPI
#include <mpi.h>
#include <pthread.h>
#endif

#include "study_sched.h"

/* how often a waiting rank looks for its message (s): short against any case, long enough
 * that waiting costs no CPU the FE of the other ranks could use */
#define POLL_S 0.01


int csx_studyHaveMpi(void) {
#ifdef CS_HAVE_MPI
  return 1;
#else
  return 0;
#endif
}


int csx_studyUnderLauncher(void) {
  /* OpenMPI's mpirun, MPICH/Hydra (PMI), PMIx launchers (srun, prun) */
  static const char* const kVars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"};
  for (size_t i = 0; i < sizeof kVars / sizeof kVars[0]; i++) {
    const char* v = getenv(kVars[i]);
    if (v && v[0]) {
      return 1;
    }
  }
  return 0;
}


/* run one case and fill res; a case-file error is reported as a failed case (it stays pending
 * on disk, so a resumed study runs it again) and kept in *first */
static void runOne(const csxStudy* s, int index, const char* dir, const csxStudyCommands* cmd,
                   int rank, csxCaseResult* res, csStatus* first, csError* err) {
  csError e;
  cs_errorClear(&e);
  csStatus st = csx_studyRunCase(s, index, dir, cmd, rank, res, &e);
  if (st != CS_OK) {
    res->state = CSX_CASE_FAILED;
    res->rank = rank;
    snprintf(res->summary, sizeof res->summary, "not recorded: %.200s", e.msg);
    if (*first == CS_OK) {
      *first = st;
      if (err) {
        *err = e;
      }
    }
  }
}


#ifdef CS_HAVE_MPI

enum { TAG_REQUEST = 11, TAG_JOB = 12, TAG_FINAL = 13, TAG_SHARE_DONE = 14 };

/* a rank's report of its finished case (index -1: its first request) */
typedef struct {
  int index;
  int state;
  int rank;
  double wall_s;
  char summary[CSX_STUDY_SUMMARY_SIZE];
} Report;

/* rank 0's queue of pending cases, shared by its case-running thread and its dispatcher */
typedef struct {
  pthread_mutex_t lock;
  const int* pending;
  int npending, next, done, nfailed;
  csxStudyProgress progress;
  void* user;
  int size;
} Queue;


static void sleepPoll(void) {
  struct timespec ts = {0, (long)(POLL_S * 1e9)};
  nanosleep(&ts, NULL);
}


/* receive one message of `tag` from `src` without spinning in MPI_Recv; *from gets the sender */
static void lazyRecv(void* buf, int bytes, int src, int tag, int* from) {
  for (;;) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(src, tag, MPI_COMM_WORLD, &flag, &st);
    if (flag) {
      MPI_Recv(buf, bytes, MPI_BYTE, st.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (from) {
        *from = st.MPI_SOURCE;
      }
      return;
    }
    sleepPoll();
  }
}


static int takeNext(Queue* q) {
  pthread_mutex_lock(&q->lock);
  int i = q->next < q->npending ? q->pending[q->next++] : -1;
  pthread_mutex_unlock(&q->lock);
  return i;
}


static void report(Queue* q, int index, const csxCaseResult* res) {
  pthread_mutex_lock(&q->lock);
  q->done++;
  q->nfailed += res->state == CSX_CASE_FAILED;
  if (q->progress) {
    q->progress(q->user, q->done, q->npending, index, res);
  }
  pthread_mutex_unlock(&q->lock);
}


/* rank 0's second thread: answers every other rank's requests until each got "no more" */
static void* dispatcher(void* arg) {
  Queue* q = arg;
  int stopped = 0;
  while (stopped < q->size - 1) {
    Report r;
    int from = -1;
    lazyRecv(&r, (int)sizeof r, MPI_ANY_SOURCE, TAG_REQUEST, &from);
    if (r.index >= 0) {
      csxCaseResult res;
      memset(&res, 0, sizeof res);
      res.state = (csxCaseState)r.state;
      res.rank = r.rank;
      res.wall_s = r.wall_s;
      r.summary[sizeof r.summary - 1] = '\0';
      snprintf(res.summary, sizeof res.summary, "%s", r.summary);
      report(q, r.index, &res);
    }
    int next = takeNext(q);
    MPI_Send(&next, 1, MPI_INT, from, TAG_JOB, MPI_COMM_WORLD);
    stopped += next < 0;
  }
  return NULL;
}

#endif /* CS_HAVE_MPI */


csStatus csx_studyMpiInit(int* argc, char*** argv, csxStudyMpi* mpi, csError* err) {
  memset(mpi, 0, sizeof *mpi);
  mpi->size = 1;
#ifdef CS_HAVE_MPI
  int already = 0; /* crawlsim-mpi initialises MPI for every command (its FE needs it) */
  MPI_Initialized(&already);
  if (!already && !csx_studyUnderLauncher()) {
    return CS_OK;
  }
  int provided = 0;
  if (already) {
    MPI_Query_thread(&provided);
  } else if (MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS) {
    return cs_errorSet(err, CS_ERR_EXTERNAL, "MPI_Init_thread failed");
  } else {
    mpi->owner = 1;
  }
  mpi->initialised = 1;
  mpi->threads_ok = provided >= MPI_THREAD_SERIALIZED;
  MPI_Comm_rank(MPI_COMM_WORLD, &mpi->rank);
  MPI_Comm_size(MPI_COMM_WORLD, &mpi->size);
#else
  (void)argc;
  (void)argv;
  (void)err;
#endif
  return CS_OK;
}


void csx_studyMpiFinalize(csxStudyMpi* mpi) {
#ifdef CS_HAVE_MPI
  if (!mpi->initialised) {
    return;
  }
  /* a barrier that sleeps: rank 0 may still be merging while the others wait */
  int token = 0;
  if (mpi->rank == 0) {
    for (int k = 1; k < mpi->size; k++) {
      lazyRecv(&token, (int)sizeof token, MPI_ANY_SOURCE, TAG_FINAL, NULL);
    }
    for (int k = 1; k < mpi->size; k++) {
      MPI_Send(&token, 1, MPI_INT, k, TAG_FINAL, MPI_COMM_WORLD);
    }
  } else {
    MPI_Send(&token, 1, MPI_INT, 0, TAG_FINAL, MPI_COMM_WORLD);
    lazyRecv(&token, (int)sizeof token, 0, TAG_FINAL, NULL);
  }
  if (mpi->owner) {
    MPI_Finalize();
  }
  mpi->initialised = mpi->owner = 0;
#else
  (void)mpi;
#endif
}


void csx_studyMpiBcastInts(const csxStudyMpi* mpi, int* v, int n) {
#ifdef CS_HAVE_MPI
  if (mpi->initialised && mpi->size > 1 && n > 0) {
    MPI_Bcast(v, n, MPI_INT, 0, MPI_COMM_WORLD);
  }
#else
  (void)mpi;
  (void)v;
  (void)n;
#endif
}


csStatus csx_studyRunPending(const csxStudy* s, const int* pending, int npending, const char* dir,
                             const csxStudyCommands* cmd, csxSchedule kind,
                             const csxStudyMpi* mpi, csxStudyProgress progress, void* user,
                             int* nfailed, csError* err) {
  csStatus first = CS_OK;
  *nfailed = 0;
  csxCaseResult res;
  /* one process, or the static split: this rank's share, in file order */
  if (mpi->size == 1 || kind == CSX_SCHEDULE_STATIC) {
    int mine = 0, done = 0;
    for (int k = mpi->rank; k < npending; k += mpi->size) {
      mine++;
    }
    for (int k = mpi->rank; k < npending; k += mpi->size) {
      runOne(s, pending[k], dir, cmd, mpi->rank, &res, &first, err);
      *nfailed += res.state == CSX_CASE_FAILED;
      if (progress) {
        progress(user, ++done, mine, pending[k], &res);
      }
    }
#ifdef CS_HAVE_MPI
    /* rank 0 merges only when every rank's share is done: each tells it, sleeping meanwhile */
    if (mpi->size > 1) {
      int token = *nfailed;
      if (mpi->rank == 0) {
        for (int k = 1; k < mpi->size; k++) {
          lazyRecv(&token, (int)sizeof token, MPI_ANY_SOURCE, TAG_SHARE_DONE, NULL);
          *nfailed += token;
        }
      } else {
        MPI_Send(&token, 1, MPI_INT, 0, TAG_SHARE_DONE, MPI_COMM_WORLD);
      }
    }
#endif
    return first;
  }
#ifdef CS_HAVE_MPI
  if (mpi->rank != 0) {
    /* a worker: ask, run, report with the next request */
    Report r;
    memset(&r, 0, sizeof r);
    r.index = -1;
    for (;;) {
      MPI_Send(&r, (int)sizeof r, MPI_BYTE, 0, TAG_REQUEST, MPI_COMM_WORLD);
      int next = -1;
      lazyRecv(&next, (int)sizeof next, 0, TAG_JOB, NULL);
      if (next < 0) {
        break;
      }
      runOne(s, next, dir, cmd, mpi->rank, &res, &first, err);
      *nfailed += res.state == CSX_CASE_FAILED;
      memset(&r, 0, sizeof r);
      r.index = next;
      r.state = (int)res.state;
      r.rank = mpi->rank;
      r.wall_s = res.wall_s;
      snprintf(r.summary, sizeof r.summary, "%s", res.summary);
    }
    return first;
  }
  /* rank 0: the dispatcher thread serves the others while this thread runs cases too */
  Queue q;
  memset(&q, 0, sizeof q);
  pthread_mutex_init(&q.lock, NULL);
  q.pending = pending;
  q.npending = npending;
  q.progress = progress;
  q.user = user;
  q.size = mpi->size;
  pthread_t th;
  if (pthread_create(&th, NULL, dispatcher, &q) != 0) {
    pthread_mutex_destroy(&q.lock);
    return cs_errorSet(err, CS_ERR_EXTERNAL, "study: cannot start the dispatcher thread");
  }
  for (int i; (i = takeNext(&q)) >= 0;) {
    runOne(s, i, dir, cmd, 0, &res, &first, err);
    report(&q, i, &res);
  }
  pthread_join(th, NULL);
  pthread_mutex_destroy(&q.lock);
  *nfailed = q.nfailed;
  return first;
#else
  return cs_errorSet(err, CS_ERR_ARG, "study: more than one rank without MPI");
#endif
}
