/* queue.c - the bounded blocking FIFO of queue.h: a ring under one mutex, two condition
 * variables (not empty, not full), and a closed flag that ends the consumers.
 */
#include "io/queue.h"

#include <stdlib.h>

#include "core/error.h"

int ww_queue_init(ww_queue *q, size_t cap) {
    WW_ASSERT(cap > 0);
    *q = (ww_queue){.cap = cap};
    q->items = calloc(cap, sizeof *q->items);
    if (!q->items) return -1;
    pthread_mutex_init(&q->lock, NULL);
    pthread_cond_init(&q->not_empty, NULL);
    pthread_cond_init(&q->not_full, NULL);
    return 0;
}

void ww_queue_free(ww_queue *q) {
    if (!q->items) return;
    pthread_cond_destroy(&q->not_full);
    pthread_cond_destroy(&q->not_empty);
    pthread_mutex_destroy(&q->lock);
    free(q->items);
    q->items = NULL;
}

void ww_queue_push(ww_queue *q, void *item) {
    WW_ASSERT(item);
    pthread_mutex_lock(&q->lock);
    while (q->count == q->cap && !q->closed) pthread_cond_wait(&q->not_full, &q->lock);
    WW_ASSERT(!q->closed);
    q->items[(q->head + q->count) % q->cap] = item;
    q->count++;
    pthread_cond_signal(&q->not_empty);
    pthread_mutex_unlock(&q->lock);
}

void *ww_queue_pop(ww_queue *q) {
    pthread_mutex_lock(&q->lock);
    while (q->count == 0 && !q->closed) pthread_cond_wait(&q->not_empty, &q->lock);
    void *item = NULL;
    if (q->count > 0) {
        item = q->items[q->head];
        q->head = (q->head + 1) % q->cap;
        q->count--;
        pthread_cond_signal(&q->not_full);
    }
    pthread_mutex_unlock(&q->lock);
    return item;
}

void ww_queue_close(ww_queue *q) {
    pthread_mutex_lock(&q->lock);
    q->closed = 1;
    pthread_cond_broadcast(&q->not_empty);
    pthread_cond_broadcast(&q->not_full);
    pthread_mutex_unlock(&q->lock);
}
