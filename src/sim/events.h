/* events.h - what happened in a step: the systems of the scripted world emit events (a stone
 * skipped, a fish bit) into an outbox in the state, cleared at the start of every step; the
 * caller reads it after the step (`simulate --events`, and later sound and the HUD). The outbox
 * exists only when the scene has such systems (ww_scene_has_objects).
 *
 * Entry i of the outbox is st->events[i * WW_SIM_EVENT_STRIDE + ...]:
 *   0 kind (ww_sim_event_kind), 1 object index, 2..4 position (m), 5 magnitude, 6 aux, 7 unused
 * Magnitude and aux are documented per kind below.
 */
#ifndef WW_EVENTS_H
#define WW_EVENTS_H

#include "sim/state.h"

#define WW_SIM_EVENTS(X)                                                                          \
    X(STONE_THROW, "stone_throw", "speed m/s")                                                   \
    X(STONE_SKIP, "stone_skip", "speed m/s after the bounce; aux: bounce number")                \
    X(STONE_SINK, "stone_sink", "speed m/s at entry")                                            \
    X(STONE_THUD, "stone_thud", "impulse N s; aux: 0 cube, 1 boat")                              \
    X(SPLASH_FULL, "splash_full", "speed m/s at impact")                                         \
    X(SPLASH_TINY, "splash_tiny", "speed m/s at impact")                                         \
    X(ROD_CAST, "rod_cast", "speed m/s")                                                         \
    X(LURE_LAND, "lure_land", "speed m/s at impact")                                             \
    X(REEL, "reel", "seconds the line was out")                                                  \
    X(BITE, "bite", "fish index in aux")                                                         \
    X(CATCH, "catch", "fish caught so far")                                                      \
    X(FISH_ESCAPE, "fish_escape", "0")                                                           \
    X(CHEST_SPAWN, "chest_spawn", "lifetime s")                                                  \
    X(CHEST_EXPIRE, "chest_expire", "0")                                                         \
    X(CHEST_COLLECT, "chest_collect", "prizes so far")                                           \
    X(CUBE_PRESS, "cube_press", "hold s")                                                        \
    X(CUBE_RELEASE, "cube_release", "release impulse N s")                                       \
    X(BOAT_START, "boat_start", "throttle")                                                      \
    X(BOAT_STOP, "boat_stop", "speed m/s")                                                       \
    X(CAMERA_BLOCKED, "camera_blocked", "distance the path was cut short, m; aux: what, see collide.h")

typedef enum ww_sim_event_kind {
    WW_SE_NONE = 0,
#define WW_SE_ENUM(id, name, magnitude) WW_SE_##id,
    WW_SIM_EVENTS(WW_SE_ENUM)
#undef WW_SE_ENUM
    WW_SE_COUNT
} ww_sim_event_kind;

/* "stone_skip", ...; "none" for 0 */
const char *ww_sim_event_name(ww_sim_event_kind k);

/* append an event to the step's outbox (pos may be NULL); a full outbox counts it in
 * st->events_dropped[0] instead */
void ww_emit(const ww_scene *sc, ww_state *st, ww_sim_event_kind kind, int object,
             const double pos[3], double magnitude, double aux);
/* empty the outbox (start of every step) */
void ww_events_clear(const ww_scene *sc, ww_state *st);
/* events in the outbox now */
int ww_events_count(const ww_scene *sc, const ww_state *st);

#endif
