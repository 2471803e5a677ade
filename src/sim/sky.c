/* sky.c - sun path and sky colours from the clock. Colours are linear RGB radiance in the
 * renderer's HDR units (exposure 1 maps a radiance of ~1 to a bright but unsaturated pixel).
 */
#include "sim/sky.h"

#include <math.h>

#include "core/mathx.h"

void ww_sky_sun_dir(double hours, double max_elevation, double dir[3]) {
    /* a = 0 at 06:00 (east, horizon), pi/2 at noon, pi at 18:00 (west) */
    double a = (hours - 6.0) / 12.0 * WW_PI;
    double se = sin(max_elevation), ce = cos(max_elevation);
    dir[0] = cos(a);
    dir[1] = sin(a) * se;
    dir[2] = -sin(a) * ce;
}

/* relative optical air mass, Kasten & Young 1989; elevation in degrees, clamped at -1 */
static double air_mass(double elev_deg) {
    double e = elev_deg < -1.0 ? -1.0 : elev_deg;
    return 1.0 / (sin(ww_m_rad(e)) + 0.50572 * pow(e + 6.07995, -1.6364));
}

static void mix3(double out[3], const double a[3], const double b[3], const double c[3],
                 double wa, double wb, double wc) {
    for (int i = 0; i < 3; i++) out[i] = wa * a[i] + wb * b[i] + wc * c[i];
}

void ww_sky_colors(const double sun_dir[3], double sun[3], double zenith[3], double horizon[3],
                   double ambient[3]) {
    double h = sun_dir[1];
    double elev = ww_m_deg(asin(ww_m_clamp(h, -1.0, 1.0)));

    /* sunlight through the air mass: Beer-Lambert with per-channel optical depth (Rayleigh plus
     * a little aerosol), faded out as the disc sets */
    static const double tau[3] = {0.14, 0.21, 0.36};
    double m = air_mass(elev), up = ww_m_smoothstep(-1.5, 1.0, elev);
    for (int i = 0; i < 3; i++) sun[i] = 3.0 * exp(-tau[i] * m) * up;

    /* day, twilight and night palettes, blended by the sun's height */
    static const double zd[3] = {0.09, 0.22, 0.55}, hd[3] = {0.50, 0.64, 0.80};
    static const double zt[3] = {0.10, 0.12, 0.26}, ht[3] = {0.95, 0.48, 0.22};
    static const double zn[3] = {0.004, 0.006, 0.016}, hn[3] = {0.010, 0.014, 0.028};
    double day = ww_m_smoothstep(0.02, 0.45, h);
    double night = 1.0 - ww_m_smoothstep(-0.22, -0.02, h);
    double twi = ww_m_clamp(1.0 - day - night, 0.0, 1.0);
    mix3(zenith, zd, zt, zn, day, twi, night);
    mix3(horizon, hd, ht, hn, day, twi, night);
    for (int i = 0; i < 3; i++) ambient[i] = 0.6 * zenith[i] + 0.4 * horizon[i];
}

void ww_sky_update(const ww_scene *sc, ww_state *st) {
    double hours = st->clock_anchor[0];
    if (sc->day_length > 0.0)
        hours += 24.0 * (st->t - st->clock_anchor[1]) / sc->day_length;
    hours = fmod(hours, 24.0);
    if (hours < 0.0) hours += 24.0;
    st->time_of_day[0] = hours;
    ww_sky_sun_dir(hours, sc->sun_max_elevation, st->sun_dir);
    ww_sky_colors(st->sun_dir, st->sun_color, st->sky_zenith, st->sky_horizon, st->ambient);
}
