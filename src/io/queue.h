/* queue.h - a bounded blocking FIFO of pointers between threads (the async writer queue of a
 * render job: the render thread hands filled frame slots to the encoder threads, which hand them
 * back through a second queue). Its capacity is fixed at creation: one allocation, none after.
 *
 *   ww_queue q; ww_queue_init(&q, cap);          // 0 ok
 *   ww_queue_push(&q, item);                     // blocks while full
 *   void *it = ww_queue_pop(&q);                 // blocks while empty; NULL once closed and empty
 *   ww_queue_close(&q);                          // wakes every waiter; pushes after it are bugs
 *   ww_queue_free(&q);                           // after every thread is done with it
 */
#ifndef WW_QUEUE_H
#define WW_QUEUE_H

#include <pthread.h>
#include <stddef.h>

typedef struct ww_queue {
    pthread_mutex_t lock;
    pthread_cond_t not_empty, not_full;
    void **items;          /* ring of cap entries */
    size_t cap, head, count;
    int closed;
} ww_queue;

int ww_queue_init(ww_queue *q, size_t cap);
void ww_queue_free(ww_queue *q);
void ww_queue_push(ww_queue *q, void *item);
void *ww_queue_pop(ww_queue *q);
void ww_queue_close(ww_queue *q);

#endif
