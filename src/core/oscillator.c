/* oscillator.c - the exact damped oscillator (oscillator.h). */
#include "core/oscillator.h"

#include <math.h>

#define OSC_STIFF_EPS 1e-12   /* w2 dt^2 below this: no spring over the step */
#define OSC_DRAG_EPS 1e-12    /* gamma dt below this: no drag over the step */

void ww_m_damped_oscillator(double w2, double gamma, double acc, double dt, double *x,
                            double *v) {
    double x0 = *x, v0 = *v;
    if (w2 * dt * dt < OSC_STIFF_EPS) {
        /* x'' = acc - gamma x': v relaxes to acc / gamma */
        if (gamma * dt < OSC_DRAG_EPS) {
            *x = x0 + v0 * dt + 0.5 * acc * dt * dt;
            *v = v0 + acc * dt;
            return;
        }
        double phi = -expm1(-gamma * dt) / gamma; /* (1 - e^(-gamma dt)) / gamma */
        *x = x0 + v0 * phi + acc * (dt - phi) / gamma;
        *v = v0 * exp(-gamma * dt) + acc * phi;
        return;
    }
    /* about the equilibrium xe = acc / w2: xi'' + gamma xi' + w2 xi = 0, a = gamma / 2,
     * sigma = w2 - a^2; xi = e^(-a t) (xi0 C + (v0 + a xi0) S) with C' = -sigma S, S' = C */
    double xe = acc / w2, xi0 = x0 - xe, a = 0.5 * gamma, sigma = w2 - a * a;
    double w0 = v0 + a * xi0, ec, es; /* e^(-a dt) C and e^(-a dt) S */
    if (sigma > 0.0) {
        double om = sqrt(sigma), e = exp(-a * dt);
        ec = e * cos(om * dt);
        es = e * sin(om * dt) / om;
    } else if (sigma < 0.0) {
        /* overdamped: products formed from exponents so cosh cannot overflow */
        double om = sqrt(-sigma), ep = exp((om - a) * dt), em = exp(-(om + a) * dt);
        ec = 0.5 * (ep + em);
        es = 0.5 * (ep - em) / om;
    } else {
        double e = exp(-a * dt);
        ec = e;
        es = e * dt;
    }
    double xi1 = xi0 * ec + w0 * es;
    *x = xe + xi1;
    *v = -a * xi1 + (-sigma * xi0 * es + w0 * ec);
}
