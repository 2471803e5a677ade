/* sky.h - the sky clock: time of day -> sun direction, sun colour, sky gradient and ambient.
 *
 * The sun rises in the east (+x) at 06:00, culminates toward the south (-z) at noon at the scene's
 * sun_max_elevation, and sets in the west (-x) at 18:00. The clock advances 24 h per day_length
 * simulated seconds from its anchor (the scene start, or the last time_of_day event).
 */
#ifndef WW_SKY_H
#define WW_SKY_H

#include "scene/scene.h"
#include "sim/state.h"

/* time of day at st->t from the clock anchor, then sun and sky colours from it */
void ww_sky_update(const ww_scene *sc, ww_state *st);

/* pure helpers (no state): unit sun direction for a clock reading, and colours for a direction */
void ww_sky_sun_dir(double hours, double max_elevation, double dir[3]);
void ww_sky_colors(const double sun_dir[3], double sun[3], double zenith[3], double horizon[3],
                   double ambient[3]);

#endif
