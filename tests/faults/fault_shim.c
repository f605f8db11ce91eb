/* fault_shim.c: an LD_PRELOAD library that makes writes or allocations fail on purpose, for the
 * fault-injection suite (tools/fault-suite.py, docs/notes/faults.md), in the manner of SQLite's
 * I/O-error and malloc-failure tests.
 *
 * Environment (all optional; without them the shim only counts):
 *   CS_FAULT_WRITE_AT=N   the N-th write event (1-based) fails, and every later one: a disk that
 *                         fills up (or a directory made read-only) and stays so. A write event
 *                         is: an open/fopen for writing, a write/pwrite to a regular file, a
 *                         stdio output call (fprintf, fputs, fputc, fwrite, vfprintf) or fflush
 *                         on a stream of a regular file, fsync, rename.
 *   CS_FAULT_ERRNO=NAME   the errno of those failures: ENOSPC (default), EROFS, EACCES, EDQUOT, EIO.
 *   CS_FAULT_MALLOC_AT=N  the N-th malloc/calloc/realloc called from the main program's own
 *                         code (our static libraries, not HDF5/ODE/libc) returns NULL (once).
 *                         Only in a process whose executable is named crawlsim.
 *   CS_FAULT_TRACE=1      print a backtrace to stderr when the fault fires (to find the caller
 *                         of a failure a trial reported badly).
 *   CS_FAULT_LOG=FILE     at exit, append "<exe> writes <n> mallocs <n> fired <0|1>" to FILE
 *                         (the suite's counting pass).
 * ENOSPC is a full disk, not a broken one: a write that stays inside a file's present size
 * (an in-place overwrite needs no new blocks), an open of an existing file without O_CREAT or
 * O_TRUNC, and fsync still succeed; under EROFS/EACCES/EIO nothing is written any more.
 * Stdio calls that fail set the stream's error flag (glibc's _IO_ERR_SEEN) as a real failed
 * write would, and fclose of such a stream returns EOF with the errno. Standard streams that
 * are not regular files (pipes, terminals) are never failed. Test code: global state is the
 * point of a preload shim. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <execinfo.h>
#include <errno.h>
#include <fcntl.h>
#include <link.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef _IO_ERR_SEEN
#define _IO_ERR_SEEN 0x20
#endif

static long g_write_at = -1, g_writes = 0;
static int g_errno = ENOSPC;
static int g_failing = 0;
static long g_malloc_at = -1, g_mallocs = 0;
static int g_malloc_fired = 0;
static int g_is_crawlsim = 0;
static uintptr_t g_lo[8], g_hi[8];
static int g_nseg = 0;
static char g_log[512] = "";
static char g_exe[256] = "";

/* real functions */
static int (*r_open)(const char*, int, ...);
static int (*r_openat)(int, const char*, int, ...);
static FILE* (*r_fopen)(const char*, const char*);
static ssize_t (*r_write)(int, const void*, size_t);
static ssize_t (*r_pwrite)(int, const void*, size_t, off_t);
static int (*r_fsync)(int);
static int (*r_rename)(const char*, const char*);
static int (*r_vfprintf)(FILE*, const char*, va_list);
static int (*r_fputs)(const char*, FILE*);
static int (*r_fputc)(int, FILE*);
static size_t (*r_fwrite)(const void*, size_t, size_t, FILE*);
static int (*r_fflush)(FILE*);
static int (*r_fclose)(FILE*);
static void* (*r_malloc)(size_t);
static void* (*r_calloc)(size_t, size_t);
static void* (*r_realloc)(void*, size_t);
static void (*r_free)(void*);

/* allocations made while dlsym resolves the allocator itself */
static char g_boot[1 << 14];
static size_t g_boot_used = 0;
static int g_in_init = 0;

static void* bootAlloc(size_t n) {
  n = (n + 15) & ~(size_t)15;
  if (g_boot_used + n > sizeof g_boot) {
    return NULL;
  }
  void* p = g_boot + g_boot_used;
  g_boot_used += n;
  return p;
}

static int isBoot(const void* p) {
  return (const char*)p >= g_boot && (const char*)p < g_boot + sizeof g_boot;
}

static void initAlloc(void) {
  g_in_init = 1;
  *(void**)&r_malloc = dlsym(RTLD_NEXT, "malloc");
  *(void**)&r_calloc = dlsym(RTLD_NEXT, "calloc");
  *(void**)&r_realloc = dlsym(RTLD_NEXT, "realloc");
  *(void**)&r_free = dlsym(RTLD_NEXT, "free");
  g_in_init = 0;
}

#define RESOLVE(name) (r_##name ? (void)0 : (void)(*(void**)&r_##name = dlsym(RTLD_NEXT, #name)))

static int segCb(struct dl_phdr_info* info, size_t size, void* data) {
  (void)size, (void)data;
  /* the first object is the main program */
  for (int i = 0; i < info->dlpi_phnum && g_nseg < 8; i++) {
    const ElfW(Phdr)* ph = &info->dlpi_phdr[i];
    if (ph->p_type == PT_LOAD && (ph->p_flags & PF_X)) {
      g_lo[g_nseg] = info->dlpi_addr + ph->p_vaddr;
      g_hi[g_nseg] = g_lo[g_nseg] + ph->p_memsz;
      g_nseg++;
    }
  }
  return 1; /* stop after the main program */
}

static int fromMain(const void* caller) {
  uintptr_t a = (uintptr_t)caller;
  for (int i = 0; i < g_nseg; i++) {
    if (a >= g_lo[i] && a < g_hi[i]) {
      return 1;
    }
  }
  return 0;
}

static int errnoNamed(const char* s) {
  if (!strcmp(s, "EROFS")) return EROFS;
  if (!strcmp(s, "EACCES")) return EACCES;
  if (!strcmp(s, "EDQUOT")) return EDQUOT;
  if (!strcmp(s, "EIO")) return EIO;
  return ENOSPC;
}

__attribute__((constructor)) static void shimInit(void) {
  const char* s;
  if ((s = getenv("CS_FAULT_WRITE_AT")) && *s) g_write_at = atol(s);
  if ((s = getenv("CS_FAULT_ERRNO")) && *s) g_errno = errnoNamed(s);
  if ((s = getenv("CS_FAULT_MALLOC_AT")) && *s) g_malloc_at = atol(s);
  if ((s = getenv("CS_FAULT_LOG")) && *s) snprintf(g_log, sizeof g_log, "%s", s);
  char exe[256];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  exe[n > 0 ? n : 0] = '\0';
  const char* base = strrchr(exe, '/');
  snprintf(g_exe, sizeof g_exe, "%s", base ? base + 1 : exe);
  g_is_crawlsim = !strcmp(g_exe, "crawlsim");
  dl_iterate_phdr(segCb, NULL);
}

__attribute__((destructor)) static void shimFini(void) {
  if (!g_log[0]) {
    return;
  }
  RESOLVE(open);
  RESOLVE(write);
  int fd = r_open(g_log, O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    char line[400];
    int k = snprintf(line, sizeof line, "%s writes %ld mallocs %ld fired %d\n", g_exe, g_writes,
                     g_mallocs, g_failing || g_malloc_fired);
    if (r_write(fd, line, (size_t)k) < 0) {
      /* nothing to do: the log is best effort */
    }
    close(fd);
  }
}

/* one write event: 1 when it must fail (errno set) */
static int event(void) {
  g_writes++;
  if (g_write_at > 0 && g_writes >= g_write_at) {
    g_failing = 1;
  }
  if (g_failing) {
    errno = g_errno;
    return 1;
  }
  return 0;
}

static int regularFd(int fd) {
  struct stat st;
  return fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
}

static int regularStream(FILE* f) {
  return f && regularFd(fileno(f));
}

static int failStream(FILE* f) {
  if (regularStream(f) && event()) {
    f->_flags |= _IO_ERR_SEEN;
    return 1;
  }
  return 0;
}

/* an open that writes; under ENOSPC an open of an existing file that neither creates nor
 * truncates is let through once the disk is full */
static int writeFlags(int flags) {
  if (g_failing && g_errno == ENOSPC && !(flags & (O_CREAT | O_TRUNC))) {
    return 0;
  }
  return (flags & (O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND)) != 0;
}

int open(const char* path, int flags, ...) {
  RESOLVE(open);
  mode_t mode = 0;
  if (flags & (O_CREAT | O_TMPFILE)) {
    va_list ap;
    va_start(ap, flags);
    mode = (mode_t)va_arg(ap, int);
    va_end(ap);
  }
  if (writeFlags(flags) && event()) {
    return -1;
  }
  return r_open(path, flags, mode);
}

int open64(const char* path, int flags, ...) {
  RESOLVE(open);
  mode_t mode = 0;
  if (flags & (O_CREAT | O_TMPFILE)) {
    va_list ap;
    va_start(ap, flags);
    mode = (mode_t)va_arg(ap, int);
    va_end(ap);
  }
  if (writeFlags(flags) && event()) {
    return -1;
  }
  return r_open(path, flags, mode);
}

int openat(int dir, const char* path, int flags, ...) {
  RESOLVE(openat);
  mode_t mode = 0;
  if (flags & (O_CREAT | O_TMPFILE)) {
    va_list ap;
    va_start(ap, flags);
    mode = (mode_t)va_arg(ap, int);
    va_end(ap);
  }
  if (writeFlags(flags) && event()) {
    return -1;
  }
  return r_openat(dir, path, flags, mode);
}

FILE* fopen(const char* path, const char* mode) {
  RESOLVE(fopen);
  if (mode && (strchr(mode, 'w') || strchr(mode, 'a') || strchr(mode, '+')) && event()) {
    return NULL;
  }
  return r_fopen(path, mode);
}

FILE* fopen64(const char* path, const char* mode) {
  return fopen(path, mode);
}

/* ENOSPC only: the write [off, off + n) lies inside the file (no new blocks) */
static int inPlace(int fd, off_t off, size_t n) {
  struct stat st;
  return g_errno == ENOSPC && off >= 0 && fstat(fd, &st) == 0 &&
         (off_t)(off + (off_t)n) <= st.st_size;
}

ssize_t write(int fd, const void* buf, size_t n) {
  RESOLVE(write);
  if (regularFd(fd) && !(g_failing && inPlace(fd, lseek(fd, 0, SEEK_CUR), n)) && event()) {
    return -1;
  }
  return r_write(fd, buf, n);
}

ssize_t pwrite(int fd, const void* buf, size_t n, off_t off) {
  RESOLVE(pwrite);
  if (regularFd(fd) && !(g_failing && inPlace(fd, off, n)) && event()) {
    return -1;
  }
  return r_pwrite(fd, buf, n, off);
}

ssize_t pwrite64(int fd, const void* buf, size_t n, off_t off) {
  return pwrite(fd, buf, n, off);
}

int fsync(int fd) {
  RESOLVE(fsync);
  if (regularFd(fd) && !(g_failing && g_errno == ENOSPC) && event()) {
    return -1;
  }
  return r_fsync(fd);
}

int rename(const char* a, const char* b) {
  RESOLVE(rename);
  if (event()) {
    return -1;
  }
  return r_rename(a, b);
}

int vfprintf(FILE* f, const char* fmt, va_list ap) {
  RESOLVE(vfprintf);
  if (failStream(f)) {
    return -1;
  }
  return r_vfprintf(f, fmt, ap);
}

int fprintf(FILE* f, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int r = vfprintf(f, fmt, ap);
  va_end(ap);
  return r;
}

int __fprintf_chk(FILE* f, int flag, const char* fmt, ...) {
  (void)flag;
  va_list ap;
  va_start(ap, fmt);
  int r = vfprintf(f, fmt, ap);
  va_end(ap);
  return r;
}

int __vfprintf_chk(FILE* f, int flag, const char* fmt, va_list ap) {
  (void)flag;
  return vfprintf(f, fmt, ap);
}

int fputs(const char* s, FILE* f) {
  RESOLVE(fputs);
  if (failStream(f)) {
    return EOF;
  }
  return r_fputs(s, f);
}

int fputc(int c, FILE* f) {
  RESOLVE(fputc);
  if (failStream(f)) {
    return EOF;
  }
  return r_fputc(c, f);
}

size_t fwrite(const void* p, size_t size, size_t n, FILE* f) {
  RESOLVE(fwrite);
  if (failStream(f)) {
    return 0;
  }
  return r_fwrite(p, size, n, f);
}

int fflush(FILE* f) {
  RESOLVE(fflush);
  if (f && failStream(f)) {
    return EOF;
  }
  return r_fflush(f);
}

int fclose(FILE* f) {
  RESOLVE(fclose);
  int failed = f && regularStream(f) && (f->_flags & _IO_ERR_SEEN) && g_failing;
  int r = r_fclose(f);
  if (failed) {
    errno = g_errno;
    return EOF;
  }
  return r;
}

/* allocation: the N-th call from the main program's code fails */
static int failAlloc(const void* caller) {
  if (!g_is_crawlsim || !fromMain(caller)) {
    return 0;
  }
  if (++g_mallocs == g_malloc_at) {
    g_malloc_fired = 1;
    if (getenv("CS_FAULT_TRACE")) {
      void* frames[24];
      int n = backtrace(frames, 24);
      backtrace_symbols_fd(frames, n, 2);
    }
    errno = ENOMEM;
    return 1;
  }
  return 0;
}

void* malloc(size_t n) {
  if (!r_malloc) {
    if (g_in_init) return bootAlloc(n);
    initAlloc();
  }
  if (failAlloc(__builtin_return_address(0))) return NULL;
  return r_malloc(n);
}

void* calloc(size_t a, size_t b) {
  if (!r_calloc) {
    if (g_in_init) {
      void* p = bootAlloc(a * b);
      if (p) memset(p, 0, a * b);
      return p;
    }
    initAlloc();
  }
  if (failAlloc(__builtin_return_address(0))) return NULL;
  return r_calloc(a, b);
}

void* realloc(void* p, size_t n) {
  if (!r_realloc) {
    initAlloc();
  }
  if (isBoot(p)) {
    void* q = r_malloc(n);
    size_t room = (size_t)(g_boot + sizeof g_boot - (char*)p);
    if (q) memcpy(q, p, n < room ? n : room);
    return q;
  }
  if (failAlloc(__builtin_return_address(0))) return NULL;
  return r_realloc(p, n);
}

void free(void* p) {
  if (!p || isBoot(p)) return;
  if (!r_free) initAlloc();
  r_free(p);
}
