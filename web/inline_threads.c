/* The web build only (cmake/web.cmake): the page runs without -pthread, so that any static
   host can serve it (real threads need SharedArrayBuffer and COOP/COEP headers). Emscripten's
   stub pthread_create fails, and std::thread with it throws. Every thread Flood starts (the
   invariant scan, a re-flood after an edit, the shrinker, a dataset's list) hands its result
   back through a flag the frame polls; here the thread's function runs to completion inside
   pthread_create, so the flag is set when the next frame looks. */
#include <errno.h>
#include <pthread.h>
#include <stdlib.h>

struct finished {
    void* result;
};

int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*),
                   void* arg) {
    (void)attr;
    struct finished* f = malloc(sizeof *f);
    if (!f) return EAGAIN;
    f->result = start(arg);
    *thread = (pthread_t)f;
    return 0;
}

int pthread_join(pthread_t thread, void** result) {
    struct finished* f = (struct finished*)thread;
    if (result) *result = f->result;
    free(f);
    return 0;
}
