/* core_sun.c: SUNDIALS contexts that never print (see core_sun.h). */
#include "core_sun.h"

#include <cvode/cvode.h>

#if SUNDIALS_VERSION_MAJOR < 7
/* CVODE 6's default handler prints to stderr: this one drops the message (the caller turns the
 * returned flag into its own csError) */
static void silentHandler(int code, const char* module, const char* fn, char* msg, void* user) {
  (void)code;
  (void)module;
  (void)fn;
  (void)msg;
  (void)user;
}
#endif


int cs_sunContextCreate(SUNContext* ctx) {
#if SUNDIALS_VERSION_MAJOR >= 7
  if (SUNContext_Create(SUN_COMM_NULL, ctx) != 0) {
    *ctx = NULL;
    return -1;
  }
  /* 7's context carries the error handlers: none, so nothing is printed */
  SUNContext_ClearErrHandlers(*ctx);
#else
  if (SUNContext_Create(NULL, ctx) != 0) {
    *ctx = NULL;
    return -1;
  }
#endif
  return 0;
}


int cs_cvodeSilence(void* cvode) {
#if SUNDIALS_VERSION_MAJOR < 7
  return CVodeSetErrHandlerFn(cvode, silentHandler, NULL) == CV_SUCCESS ? 0 : -1;
#else
  return cvode ? 0 : -1;
#endif
}
