/* @NAME@: the fixed-step stepper of the hydroservo model '@MODEL@' (API and use: @NAME@.h).
 *
 * The model's functions are CasADi's generated code in @NAME@_model.c, written on the scaled states
 * z = x / x_nom (x_nom: the nominal magnitude each component declares for its states), so that one
 * tolerance means the same for a pressure of 1e7 Pa and a spool position of 1e-5 m:
 *     @NAME@_f(t, z, p) = dz/dt,  @NAME@_jac(t, z, p) = d(dz/dt)/dz (dense, column-major),
 *     @NAME@_y(t, z, p) = outputs,  @NAME@_z0(p) = initial scaled states,
 *     @NAME@_conv(t, z, p) = last Newton correction of each algebraic unknown (models that have some),
 * with p the parameters followed by the inputs; each also takes q = @NAME@_q(p), the parts of its
 * expressions that depend on the parameters alone, evaluated once per change of p (@NAME@_call).
 *
 * rk4: the classical fourth-order Runge-Kutta method.
 * bdf2: the two-step backward differentiation formula at the fixed step h,
 *     z1 - 4/3 z0 + 1/3 z_prev = 2/3 h f(t1, z1),
 * started by one implicit-Euler step (z1 - z0 = h f(t1, z1)) after a reset or a changed state. Each step
 * solves its equation by Newton's method with the exact Jacobian from the linear extrapolation of the last
 * two states: first with the factorisation (LU, partial pivoting) of I - gamma J (gamma = 2h/3, or h) kept
 * from an earlier step, as long as every iteration shrinks the correction by @UPPER@_RATE; if it does not,
 * again from the extrapolation with the Jacobian evaluated and factorised at every iterate. A step that
 * has not converged in @UPPER@_MAX_ITERATIONS iterations of that second attempt is refused. Converged:
 * the last correction of every scaled state is at most @UPPER@_TOLERANCE (the error left is no larger,
 * for iterations that shrink by half or faster).
 *
 * Both evaluate the model on [t0, t1) of each step (@NAME@_end): a source that jumps at a step boundary
 * acts from the next step on, as in CVODES' solution.
 *
 * @NAME@_integrate: variable steps with error control, from the instance's time and states through a list of
 * output times (each of them the end of a step), with the method of the run's choosing:
 * dopri5: the explicit Runge-Kutta pair of Dormand and Prince, order 5 with an embedded order-4 error
 *     estimate, seven stages of which the last is the next step's first ([Dormand1980]; [Hairer1993],
 *     Table II.5.2);
 * ros23: the linearly implicit Rosenbrock pair of Shampine and Reichelt, order 2 with an order-3 error
 *     estimate, L-stable, on the exact Jacobian and the exact time derivative of the rates
 *     ([Shampine1997] section 3; Rosenbrock methods: [Hairer1996] section IV.7), for stiff circuits;
 * rodas3: the linearly implicit Rosenbrock pair RODAS3 of Sandu et al., order 3 with an order-2 error
 *     estimate, L-stable and stiffly accurate, on the same Jacobian and time derivative ([Sandu1997]), for
 *     stiff circuits at the accuracies ros23 needs many steps for.
 * The error of a step is the root mean square over the scaled states of
 *     err_i / (atol + rtol max(|z0_i|, |z1_i|))
 * and a step is accepted when it is at most 1; the next step is h (1/err)^(1/(q+1)) times 0.9, within 0.2
 * and 5 times h (not growing after a rejection), with q + 1 = 5 (dopri5) or 3 (ros23, rodas3) ([Hairer1993] section
 * II.4). The first step follows [Hairer1993] section II.4, "Starting step size". No step is longer than
 * max_step (if given) nor passes an output time: each output time ends a step (so that an input changing
 * between two of them is not stepped over unseen), and output times closer together than a step can be share
 * one. Within a step the solution is the cubic Hermite interpolant of the states and rates at both ends (third
 * order; [Hairer1993] section II.6), on which events are located. Events: where a switching
 * function the components declare (an end stop, a lap edge, a valve cracking, a source's step: the kinks and
 * jumps of the equations) changes side within a step, the crossing is found by bisection on the interpolant
 * and the step taken again to end just past it, before its error is judged, so that no step straddles a kink;
 * step-size control goes on from that step (never longer than the step before the event).
 */
#include "@NAME@.h"
#include "@NAME@_model.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define @UPPER@_AT_LEAST_1(n) ((n) > 0 ? (n) : 1)
/* @NAME@_integrate: every this many steps, a run that advanced by less than 1e-9 of its span is stuck */
#define @UPPER@_STUCK_STEPS 10000
#define @UPPER@_NP (@UPPER@_N_PARAMETERS + @UPPER@_N_INPUTS)
#define @UPPER@_NZ @UPPER@_AT_LEAST_1(@UPPER@_N_STATES)

/* The model's data, the method's settings and the work space of the generated functions (the largest any
 * of them needs), written by hydroservo: */
@DATA@

struct @NAME@_instance {
    long long steps; /* since the reset (or the end of @NAME@_integrate): t = t_start + steps h */
    double t_start;
    long long iterations, jacobians;
    long long accepted, rejected, evaluations, events; /* @NAME@_integrate, since the reset */
    int outputs_current; /* y holds the outputs of the current time, states and inputs */
    int q_current;       /* q holds the derived parameters of the current parameters and inputs */
    double q[@UPPER@_AT_LEAST_1(@UPPER@_N_DERIVED)]; /* parameter-only parts of the model's expressions */
    int history;         /* bdf2: z_prev holds the state one step back */
    int factorised;      /* bdf2: lu holds I - gamma J for gamma = lu_gamma */
    double lu_gamma;
    double p[@UPPER@_AT_LEAST_1(@UPPER@_NP)]; /* the parameters, then the inputs */
    double z[@UPPER@_NZ], z_prev[@UPPER@_NZ], z_new[@UPPER@_NZ];
    double y[@UPPER@_AT_LEAST_1(@UPPER@_N_OUTPUTS)];
    double k[7][@UPPER@_NZ]; /* rk4, dopri5, ros23: the stages; bdf2: the predictor, the constant part, the correction */
    double z_host[@UPPER@_NZ]; /* the continuous-time functions: the host's states, scaled */
    double f0[@UPPER@_NZ], f1[@UPPER@_NZ], dfdt[@UPPER@_NZ]; /* @NAME@_integrate: rates at both ends, df/dt */
    double jac[@UPPER@_NZ * @UPPER@_NZ]; /* ros23: the Jacobian at the step's start */
    double g1[@UPPER@_AT_LEAST_1(@UPPER@_N_SWITCHES)], gm[@UPPER@_AT_LEAST_1(@UPPER@_N_SWITCHES)]; /* events */
    signed char side[@UPPER@_AT_LEAST_1(@UPPER@_N_SWITCHES)]; /* each switching function's last side: -1, 0, 1 */
    double lu[@UPPER@_NZ * @UPPER@_NZ];
    int pivot[@UPPER@_NZ];
    const casadi_real *arg[@UPPER@_SZ_ARG];
    casadi_real *res[@UPPER@_SZ_RES];
    casadi_int iw[@UPPER@_AT_LEAST_1(@UPPER@_SZ_IW)];
    casadi_real w[@UPPER@_AT_LEAST_1(@UPPER@_SZ_W)];
    const volatile int *stop; /* @NAME@_set_stop: the host's flag, read before every step (NULL: none) */
    char message[512];
};

/* The generated functions, called with the instance's work space. They are built from scalar expressions
 * (CasADi SX) and cannot fail: their return value is always 0. */
typedef int (*@NAME@_function)(const casadi_real **, casadi_real **, casadi_int *, casadi_real *, int);

static void @NAME@_call(@NAME@_instance *m, @NAME@_function fn, const double *t, const double *z, double *out) {
    if (t != NULL) {
        if (!m->q_current) { /* the derived parameters, once per change of the parameters or inputs */
            m->arg[0] = m->p;
            m->res[0] = m->q;
            @NAME@_q(m->arg, m->res, m->iw, m->w, 0);
            m->q_current = 1;
        }
        m->arg[0] = t;
        m->arg[1] = z;
        m->arg[2] = m->p;
        m->arg[3] = m->q;
    } else {
        m->arg[0] = m->p;
    }
    m->res[0] = out;
    fn(m->arg, m->res, m->iw, m->w, 0);
}

static void @NAME@_rates_scaled(@NAME@_instance *m, double t, const double *z, double *dz) {
    @NAME@_call(m, @NAME@_f, &t, z, dz);
}

/* The time after `steps` steps from t_start [s]: a product, so that no rounding error accumulates. */
static double @NAME@_now(const @NAME@_instance *m, long long steps) {
    return m->t_start + (double)steps * @UPPER@_STEP;
}

/* The end of the step that starts after `steps` steps, as the model sees it: the largest time below
 * t1 = (steps + 1) h. A step evaluates the model on [t0, t1) only, so that a source that jumps at t1
 * (a Step at t_step = t1) acts from the next step on, as it does in CVODES' solution, rather than
 * entering the last stage of this one (for rk4 the jump then costs nothing of its order; bdf2's two-step
 * formula still spans it, and is first order across it). */
static double @NAME@_end(const @NAME@_instance *m, long long steps) {
    return nextafter(@NAME@_now(m, steps + 1), -HUGE_VAL);
}

/* The first state of z that is NaN or infinite, or -1. */
static int @NAME@_not_finite(const double *z) {
    for (int i = 0; i < @UPPER@_N_STATES; ++i) {
        if (!isfinite(z[i])) return i;
    }
    return -1;
}

/* @UPPER@_OK if the algebraic unknowns are solved at (t, z) (always, for a model without any), else
 * @UPPER@_ALGEBRAIC with the message. */
static int @NAME@_algebraic(@NAME@_instance *m, double t, const double *z) {
#if @UPPER@_N_ALGEBRAIC > 0
    double correction[@UPPER@_N_ALGEBRAIC];
    @NAME@_call(m, @NAME@_conv, &t, z, correction);
    for (int j = 0; j < @UPPER@_N_ALGEBRAIC; ++j) {
        if (!(correction[j] <= @UPPER@_ALGEBRAIC_TOLERANCE)) {
            snprintf(m->message, sizeof m->message,
                     "t = %.9g s: the algebraic unknown %s was not solved: the last of its Newton steps corrected "
                     "it by %.3g of its nominal magnitude (accepted: %.3g)",
                     t, @NAME@_algebraic_names[j], correction[j], @UPPER@_ALGEBRAIC_TOLERANCE);
            return @UPPER@_ALGEBRAIC;
        }
    }
#else
    (void)m, (void)t, (void)z;
#endif
    return @UPPER@_OK;
}

/* LU factorisation with partial pivoting of the n x n column-major matrix a, in place (P a = L U, unit
 * lower L); rows are swapped whole, as LAPACK's dgetrf does. Returns 0, or 1 if a pivot is zero or not finite. */
static int @NAME@_lu(double *a, int *pivot, int n) {
    for (int k = 0; k < n; ++k) {
        int p = k;
        double largest = fabs(a[k + n * k]);
        for (int i = k + 1; i < n; ++i) {
            if (fabs(a[i + n * k]) > largest) {
                largest = fabs(a[i + n * k]);
                p = i;
            }
        }
        pivot[k] = p;
        if (!(largest > 0.0) || !isfinite(largest)) return 1;
        if (p != k) {
            for (int j = 0; j < n; ++j) {
                double swap = a[k + n * j];
                a[k + n * j] = a[p + n * j];
                a[p + n * j] = swap;
            }
        }
        for (int i = k + 1; i < n; ++i) a[i + n * k] /= a[k + n * k];
        for (int j = k + 1; j < n; ++j) {
            double akj = a[k + n * j];
            if (akj != 0.0) {
                for (int i = k + 1; i < n; ++i) a[i + n * j] -= a[i + n * k] * akj;
            }
        }
    }
    return 0;
}

/* Solve (L U) x = P b with the factors of @NAME@_lu; b is overwritten by x. */
static void @NAME@_lu_solve(const double *lu, const int *pivot, int n, double *b) {
    for (int k = 0; k < n; ++k) {
        if (pivot[k] != k) {
            double swap = b[k];
            b[k] = b[pivot[k]];
            b[pivot[k]] = swap;
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = j + 1; i < n; ++i) b[i] -= lu[i + n * j] * b[j];
    }
    for (int j = n - 1; j >= 0; --j) {
        b[j] /= lu[j + n * j];
        for (int i = 0; i < j; ++i) b[i] -= lu[i + n * j] * b[j];
    }
}

#if @UPPER@_BDF2
/* Evaluate the Jacobian at (t, z) and factorise I - gamma J. Returns 0 or @UPPER@_SINGULAR. */
static int @NAME@_factorise(@NAME@_instance *m, double t, const double *z, double gamma) {
    const int n = @UPPER@_N_STATES;
    @NAME@_call(m, @NAME@_jac, &t, z, m->lu);
    for (int i = 0; i < n * n; ++i) m->lu[i] *= -gamma;
    for (int i = 0; i < n; ++i) m->lu[i + n * i] += 1.0;
    m->jacobians += 1;
    m->factorised = @NAME@_lu(m->lu, m->pivot, n) == 0;
    m->lu_gamma = gamma;
    if (!m->factorised) {
        snprintf(m->message, sizeof m->message,
                 "t = %.9g s: the Newton matrix I - gamma J is singular (gamma = %.6g s); the model has no "
                 "unique solution at this step",
                 t, gamma);
        return @UPPER@_SINGULAR;
    }
    return @UPPER@_OK;
}

/* Newton's iterations on z - known - gamma f(t1, z) = 0 from z = m->z_new: with the factorisation kept (each
 * iteration must shrink the correction by @UPPER@_RATE), or with the Jacobian evaluated and factorised at
 * every iterate (full). Returns 0 once the last correction of every state is at most @UPPER@_TOLERANCE,
 * 1 if the iterations stop first (*size: the last correction, *worst: its state), or a status. */
static int @NAME@_newton(@NAME@_instance *m, double t1, double gamma, const double *known, int full, double *size,
                         int *worst, int *iterations) {
    const int n = @UPPER@_N_STATES;
    double *z = m->z_new, *d = m->k[2], previous = HUGE_VAL;
    for (*iterations = 0; *iterations < @UPPER@_MAX_ITERATIONS;) {
        if (full) {
            int status = @NAME@_factorise(m, t1, z, gamma);
            if (status) return status;
        }
        @NAME@_rates_scaled(m, t1, z, d);
        for (int i = 0; i < n; ++i) d[i] = z[i] - known[i] - gamma * d[i];
        @NAME@_lu_solve(m->lu, m->pivot, n, d);
        *size = 0.0;
        for (int i = 0; i < n; ++i) {
            z[i] -= d[i];
            if (!(fabs(d[i]) <= *size)) { /* NaN counts as largest */
                *size = fabs(d[i]);
                *worst = i;
            }
        }
        *iterations += 1;
        m->iterations += 1;
        if (*size <= @UPPER@_TOLERANCE) return 0;
        if (isnan(*size) || (!full && !(*size <= @UPPER@_RATE * previous))) return 1;
        previous = *size;
    }
    return 1;
}

/* One bdf2 step (implicit Euler when there is no previous state) into m->z_new: from the linear extrapolation
 * of the last two states, Newton's iterations with the factorisation kept from earlier steps, and, if they
 * do not converge fast, again with the Jacobian at every iterate. */
static int @NAME@_advance(@NAME@_instance *m) {
    const int n = @UPPER@_N_STATES;
    const double h = @UPPER@_STEP, t1 = @NAME@_end(m, m->steps);
    const double gamma = m->history ? 2.0 * h / 3.0 : h;
    double *predicted = m->k[0], *known = m->k[1], size = 0.0;
    int worst = 0, iterations = 0, status = 1;
    for (int i = 0; i < n; ++i) {
        predicted[i] = m->history ? 2.0 * m->z[i] - m->z_prev[i] : m->z[i];
        known[i] = m->history ? (4.0 * m->z[i] - m->z_prev[i]) / 3.0 : m->z[i];
    }
    for (int full = !m->factorised || m->lu_gamma != gamma; full < 2 && status == 1; ++full) {
        memcpy(m->z_new, predicted, sizeof(double) * (size_t)n);
        status = @NAME@_newton(m, t1, gamma, known, full, &size, &worst, &iterations);
    }
    if (status == 1) {
        snprintf(m->message, sizeof m->message,
                 "t = %.9g s: Newton's iterations did not converge (%d iterations, each with a new Jacobian; "
                 "last correction of %s: %.3g of its nominal magnitude, accepted: %.3g); the step %.6g s is too "
                 "long for the model's fastest dynamics here, or the model has no solution",
                 @NAME@_now(m, m->steps + 1), iterations, @NAME@_state_names[worst], size, @UPPER@_TOLERANCE, h);
        m->factorised = 0;
        return @UPPER@_NOT_CONVERGED;
    }
    return status;
}
#else
/* One classical Runge-Kutta step into m->z_new. */
static int @NAME@_advance(@NAME@_instance *m) {
    const int n = @UPPER@_N_STATES;
    const double h = @UPPER@_STEP, t0 = @NAME@_now(m, m->steps), t1 = @NAME@_end(m, m->steps);
    double *s = m->z_new;
    @NAME@_rates_scaled(m, t0, m->z, m->k[0]);
    for (int i = 0; i < n; ++i) s[i] = m->z[i] + 0.5 * h * m->k[0][i];
    @NAME@_rates_scaled(m, t0 + 0.5 * h, s, m->k[1]);
    for (int i = 0; i < n; ++i) s[i] = m->z[i] + 0.5 * h * m->k[1][i];
    @NAME@_rates_scaled(m, t0 + 0.5 * h, s, m->k[2]);
    for (int i = 0; i < n; ++i) s[i] = m->z[i] + h * m->k[2][i];
    @NAME@_rates_scaled(m, t1, s, m->k[3]);
    for (int i = 0; i < n; ++i) {
        s[i] = m->z[i] + h / 6.0 * (m->k[0][i] + 2.0 * (m->k[1][i] + m->k[2][i]) + m->k[3][i]);
    }
    return @UPPER@_OK;
}
#endif

/* ---- @NAME@_integrate: the adaptive solvers ------------------------------------------------------------- */

/* dopri5 ([Hairer1993] Table II.5.2): nodes, coefficients, and the error weights b - b^ of the embedded pair. */
static const double @NAME@_dp_c[7] = {0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0};
static const double @NAME@_dp_a[7][6] = {
    {0.0},
    {0.2},
    {3.0 / 40.0, 9.0 / 40.0},
    {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0},
    {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0},
    {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0},
    {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0},
};
static const double @NAME@_dp_e[7] = {71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0,
                                      22.0 / 525.0, -1.0 / 40.0};

/* The scaled error norm of a step: the root mean square of err_i / (atol + rtol max(|z0_i|, |z1_i|)). */
static double @NAME@_error_norm(const double *err, const double *z0, const double *z1, double rtol, double atol) {
    double sum = 0.0;
    for (int i = 0; i < @UPPER@_N_STATES; ++i) {
        double scale = atol + rtol * fmax(fabs(z0[i]), fabs(z1[i]));
        double r = err[i] / scale;
        sum += r * r;
    }
    double norm = sqrt(sum / @UPPER@_AT_LEAST_1(@UPPER@_N_STATES));
    return isfinite(norm) ? norm : HUGE_VAL;
}

/* One dopri5 step of h from (t, m->z) with m->f0 = f(t, z): m->z_new, m->f1 = f(t + h, z_new) (the next step's
 * first stage), and the error estimate in m->k[6]'s place (err). */
static void @NAME@_dopri5(@NAME@_instance *m, double t, double h, double *err) {
    const int n = @UPPER@_N_STATES;
    double *s = m->z_new;
    memcpy(m->k[0], m->f0, sizeof(double) * (size_t)n);
    for (int stage = 1; stage < 7; ++stage) {
        for (int i = 0; i < n; ++i) {
            double sum = 0.0;
            for (int j = 0; j < stage; ++j) sum += @NAME@_dp_a[stage][j] * m->k[j][i];
            s[i] = m->z[i] + h * sum;
        }
        double *k = stage < 6 ? m->k[stage] : m->f1;
        @NAME@_rates_scaled(m, stage < 6 ? t + @NAME@_dp_c[stage] * h : t + h, s, k);
    }
    m->evaluations += 6;
    for (int i = 0; i < n; ++i) {
        double e = @NAME@_dp_e[6] * m->f1[i];
        for (int j = 0; j < 6; ++j) e += @NAME@_dp_e[j] * m->k[j][i];
        err[i] = h * e;
    }
}

/* ros23 ([Shampine1997]): d = 1/(2 + sqrt 2), e32 = 6 + sqrt 2, W = I - h d J, T = df/dt, at (t, z):
 *     k1 = W^-1 (F0 + h d T),  F1 = f(t + h/2, z + h k1 / 2),  k2 = W^-1 (F1 - k1) + k1,  z1 = z + h k2,
 *     F2 = f(t + h, z1),  k3 = W^-1 (F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T),  err = h (k1 - 2 k2 + k3) / 6.
 * m->jac and m->dfdt hold J and T at (t, z). Returns 0, or 1 if W is singular. */
static int @NAME@_ros23(@NAME@_instance *m, double t, double h, double *err) {
    const int n = @UPPER@_N_STATES;
    const double d = 1.0 / (2.0 + sqrt(2.0)), e32 = 6.0 + sqrt(2.0);
    double *k1 = m->k[0], *k2 = m->k[1], *k3 = m->k[2], *F1 = m->k[3], *s = m->z_new;
    for (int i = 0; i < n * n; ++i) m->lu[i] = -h * d * m->jac[i];
    for (int i = 0; i < n; ++i) m->lu[i + n * i] += 1.0;
    if (@NAME@_lu(m->lu, m->pivot, n)) return 1;
    for (int i = 0; i < n; ++i) k1[i] = m->f0[i] + h * d * m->dfdt[i];
    @NAME@_lu_solve(m->lu, m->pivot, n, k1);
    for (int i = 0; i < n; ++i) s[i] = m->z[i] + 0.5 * h * k1[i];
    @NAME@_rates_scaled(m, t + 0.5 * h, s, F1);
    for (int i = 0; i < n; ++i) k2[i] = F1[i] - k1[i];
    @NAME@_lu_solve(m->lu, m->pivot, n, k2);
    for (int i = 0; i < n; ++i) {
        k2[i] += k1[i];
        s[i] = m->z[i] + h * k2[i];
    }
    @NAME@_rates_scaled(m, t + h, s, m->f1);
    for (int i = 0; i < n; ++i) {
        k3[i] = m->f1[i] - e32 * (k2[i] - F1[i]) - 2.0 * (k1[i] - m->f0[i]) + h * d * m->dfdt[i];
    }
    @NAME@_lu_solve(m->lu, m->pivot, n, k3);
    for (int i = 0; i < n; ++i) err[i] = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]);
    m->evaluations += 2;
    return 0;
}

/* rodas3 ([Sandu1997]; Rosenbrock methods: [Hairer1996] section IV.7): 4 stages, order 3 with an embedded
 * order-2 error estimate, L-stable and stiffly accurate (R(inf) = 0: a stiff transient is damped within the
 * step, and the estimate sees what the step leaves of it). With W = I/(gamma h) - J, gamma = 1/2, T = df/dt:
 *     W K1 = f0 + h T / 2,                    W K2 = f0 + 4 K1 / h + 3 h T / 2,
 *     W K3 = f(t + h, z + 2 K1) + (K1 - K2) / h,
 *     W K4 = f(t + h, z + 2 K1 + K3) + (K1 - K2 - 8 K3 / 3) / h,
 *     z1 = z + 2 K1 + K3 + K4,  err = K4;
 * 2 evaluations of f per step, and f(t + h, z1) for the interpolant and the next step. m->jac and m->dfdt hold
 * J and T at (t, z). Returns 0, or 1 if W is singular. */
static int @NAME@_rodas3(@NAME@_instance *m, double t, double h, double *err) {
    const int n = @UPPER@_N_STATES;
    double *K1 = m->k[0], *K2 = m->k[1], *K3 = m->k[2], *F = m->k[3], *s = m->z_new;
    const double *T = m->dfdt;
    for (int i = 0; i < n * n; ++i) m->lu[i] = -m->jac[i];
    for (int i = 0; i < n; ++i) m->lu[i + n * i] += 2.0 / h;
    if (@NAME@_lu(m->lu, m->pivot, n)) return 1;
    for (int i = 0; i < n; ++i) {
        K1[i] = m->f0[i] + 0.5 * h * T[i];
    }
    @NAME@_lu_solve(m->lu, m->pivot, n, K1);
    for (int i = 0; i < n; ++i) {
        K2[i] = m->f0[i] + 4.0 * K1[i] / h + 1.5 * h * T[i];
        s[i] = m->z[i] + 2.0 * K1[i];
    }
    @NAME@_lu_solve(m->lu, m->pivot, n, K2);
    @NAME@_rates_scaled(m, t + h, s, F);
    for (int i = 0; i < n; ++i) K3[i] = F[i] + (K1[i] - K2[i]) / h;
    @NAME@_lu_solve(m->lu, m->pivot, n, K3);
    for (int i = 0; i < n; ++i) s[i] = m->z[i] + 2.0 * K1[i] + K3[i];
    @NAME@_rates_scaled(m, t + h, s, F);
    for (int i = 0; i < n; ++i) err[i] = F[i] + (K1[i] - K2[i] - 8.0 / 3.0 * K3[i]) / h;
    @NAME@_lu_solve(m->lu, m->pivot, n, err);
    for (int i = 0; i < n; ++i) s[i] += err[i];
    @NAME@_rates_scaled(m, t + h, s, m->f1);
    m->evaluations += 3;
    return 0;
}

/* The cubic Hermite interpolant at t in [t0, t0 + h] from the states and rates at both ends, scaled. */
static void @NAME@_hermite(const @NAME@_instance *m, double t0, double h, double t, double *z) {
    const double s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    for (int i = 0; i < @UPPER@_N_STATES; ++i) {
        z[i] = h00 * m->z[i] + h10 * h * m->f0[i] + h01 * m->z_new[i] + h11 * h * m->f1[i];
    }
}

/* Row k of the results: the states (in their units) and the outputs at time t, scaled states z. */
static void @NAME@_record(@NAME@_instance *m, long k, double t, const double *z, double *states, double *outputs) {
    if (states != NULL) {
        for (int i = 0; i < @UPPER@_N_STATES; ++i) states[k * @UPPER@_N_STATES + i] = z[i] * @NAME@_nominal[i];
    }
    if (outputs != NULL && @UPPER@_N_OUTPUTS > 0) {
        @NAME@_call(m, @NAME@_y, &t, z, outputs + k * @UPPER@_N_OUTPUTS);
    }
}

/* The first step ([Hairer1993] section II.4): from the sizes of the states and the rates, refined by the
 * change of the rates over one explicit Euler step; order is the method's. */
static double @NAME@_first_step(@NAME@_instance *m, double t, double span, double rtol, double atol, int order) {
    const int n = @UPPER@_N_STATES;
    double d0 = 0.0, d1 = 0.0, d2 = 0.0, h0, h1;
    for (int i = 0; i < n; ++i) {
        double scale = atol + rtol * fabs(m->z[i]);
        d0 += (m->z[i] / scale) * (m->z[i] / scale);
        d1 += (m->f0[i] / scale) * (m->f0[i] / scale);
    }
    d0 = sqrt(d0 / n), d1 = sqrt(d1 / n);
    h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0 = fmin(h0, span);
    for (int i = 0; i < n; ++i) m->z_new[i] = m->z[i] + h0 * m->f0[i];
    @NAME@_rates_scaled(m, t + h0, m->z_new, m->f1);
    m->evaluations += 1;
    for (int i = 0; i < n; ++i) {
        double scale = atol + rtol * fabs(m->z[i]);
        double r = (m->f1[i] - m->f0[i]) / scale;
        d2 += r * r;
    }
    d2 = sqrt(d2 / n) / h0;
    if (!isfinite(d2)) return 1e-3 * h0;
    double largest = fmax(d1, d2);
    h1 = largest <= 1e-15 ? fmax(1e-6, 1e-3 * h0) : pow(0.01 / largest, 1.0 / (order + 1));
    return fmin(fmin(100.0 * h0, h1), span);
}

#if @UPPER@_N_SWITCHES > 0
/* A switching function's side: -1, 1, or 0 within 1e-9 of its nominal magnitude of zero (on the kink). */
static int @NAME@_side(double value, int i) {
    const double band = 1e-9 * @NAME@_switch_nominal[i];
    return value > band ? 1 : (value < -band ? -1 : 0);
}

/* The switching functions at (t, z) into g. */
static void @NAME@_switches(@NAME@_instance *m, double t, const double *z, double *g) {
    @NAME@_call(m, @NAME@_g, &t, z, g);
}

/* Events: after an accepted step from t0 to t1 (m->z to m->z_new), m->g1 holds the switching functions at t1;
 * for each that has changed side since its last side, the time it did, by bisection on the step's interpolant
 * (to 1e-12 of the step). Returns 1 and the earliest such time in *t_cross, or 0. */
static int @NAME@_crossing(@NAME@_instance *m, double t0, double h, double t1, double *t_cross) {
    int any = 0;
    double earliest = t1;
    @NAME@_switches(m, t1, m->z_new, m->g1);
    for (int i = 0; i < @UPPER@_N_SWITCHES; ++i) {
        int now = @NAME@_side(m->g1[i], i);
        if (now == 0 || m->side[i] == 0 || now == m->side[i]) continue;
        double lo = t0, hi = t1;
        for (int k = 0; k < 60 && hi - lo > 1e-12 * h; ++k) {
            double mid = 0.5 * (lo + hi);
            @NAME@_hermite(m, t0, h, mid, m->z_host);
            @NAME@_switches(m, mid, m->z_host, m->gm);
            if (@NAME@_side(m->gm[i], i) == now) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        if (hi < earliest) earliest = hi;
        any = 1;
    }
    *t_cross = earliest;
    return any;
}
#endif

int @NAME@_integrate(@NAME@_instance *m, int method, int events, double rtol, double atol, double max_step,
                     long max_steps, long n_times, const double *times, double *states, double *outputs) {
    const int n = @UPPER@_N_STATES;
    if ((method != @UPPER@_DOPRI5 && method != @UPPER@_ROS23 && method != @UPPER@_RODAS3) || !(rtol > 0.0 && rtol < 1.0) ||
        !(atol > 0.0 && atol <= 1.0) || !(max_step >= 0.0) || max_steps < 1 || n_times < 1 || times == NULL) {
        snprintf(m->message, sizeof m->message,
                 "integrate: expected method 1 (dopri5), 2 (ros23) or 3 (rodas3), 0 < rtol < 1, 0 < atol <= 1, max_step >= 0, "
                 "max_steps >= 1 and at least one output time");
        return @UPPER@_BAD_ARGUMENT;
    }
    double hmax = 0.0;
    for (long k = 1; k < n_times; ++k) {
        if (!(times[k] > times[k - 1])) {
            snprintf(m->message, sizeof m->message, "integrate: output time %ld (%.9g s) is not after the one before",
                     k, times[k]);
            return @UPPER@_BAD_ARGUMENT;
        }
    }
    hmax = times[n_times - 1] - times[0];
    const double same_time = 1e-12 * hmax;
    if (max_step > 0.0) hmax = fmin(hmax, max_step);
    const int explicit_method = method == @UPPER@_DOPRI5;
    const int order = method == @UPPER@_DOPRI5 ? 4 : 2; /* of the error estimate */
    const double exponent = 1.0 / (order + 1);
    const char *method_name = method == @UPPER@_DOPRI5 ? "dopri5" : (method == @UPPER@_RODAS3 ? "rodas3" : "ros23");
    double t = times[0], t_end = times[n_times - 1], *err = m->k[6];
    long out = 1, taken = 0, taken_mark = 0;
    double t_mark = times[0];
    int rejected_last = 0, status = @UPPER@_OK;
    @NAME@_record(m, 0, t, m->z, states, outputs);
    if (n_times == 1) return @UPPER@_OK;
    if (n == 0) {
        for (; out < n_times; ++out) @NAME@_record(m, out, times[out], m->z, states, outputs);
        m->t_start = t_end, m->steps = 0;
        return @UPPER@_OK;
    }
    @NAME@_rates_scaled(m, t, m->z, m->f0);
    m->evaluations += 1;
    int bad = @NAME@_not_finite(m->f0);
    if (bad >= 0) {
        snprintf(m->message, sizeof m->message, "t = %.9g s: the rate of the state %s is %g at the start", t,
                 @NAME@_state_names[bad], m->f0[bad] * @NAME@_nominal[bad]);
        return @UPPER@_NOT_FINITE;
    }
    const int method_order = method == @UPPER@_DOPRI5 ? 5 : (method == @UPPER@_RODAS3 ? 3 : 2);
    double h = fmin(@NAME@_first_step(m, t, t_end - t, rtol, atol, method_order), hmax);
    int have_jacobian = 0, event_step = 0;
    double h_resume = h;
#if @UPPER@_N_SWITCHES > 0
    @NAME@_switches(m, t, m->z, m->g1);
    for (int i = 0; i < @UPPER@_N_SWITCHES; ++i) m->side[i] = (signed char)@NAME@_side(m->g1[i], i);
#endif
    while (out < n_times) {
        if (m->stop != NULL && *m->stop) {
            snprintf(m->message, sizeof m->message, "t = %.9g s: interrupted (the host's stop flag was set)", t);
            status = @UPPER@_INTERRUPTED;
            break;
        }
        if (taken >= max_steps) {
            snprintf(m->message, sizeof m->message,
                     "t = %.9g s: the step budget of %ld steps was used up (last step %.3g s, mean step %.3g s; "
                     "%.3g s of the %.3g s asked for were done); the dynamics are too fast for the time span%s, or a "
                     "state diverges",
                     t, max_steps, h, (t - times[0]) / (double)max_steps, t - times[0], t_end - times[0],
                     explicit_method ? " (stiff? ros23 is for stiff circuits)" : "");
            status = @UPPER@_TOO_MUCH_WORK;
            break;
        }
        if (taken - taken_mark >= @UPPER@_STUCK_STEPS) { /* a run that no longer advances fails now, not at the budget */
            if (t - t_mark < 1e-9 * (t_end - times[0])) {
                const double mean = (t - t_mark) / (double)(taken - taken_mark);
                snprintf(m->message, sizeof m->message,
                         "t = %.9g s: the last %ld steps advanced by %.3g s in all (mean step %.3g s); at that pace the "
                         "%.3g s left of the %.3g s asked for would take %.2g steps (budget %ld): the step control is "
                         "stuck at a kink or a jump of the rates here, or the span is far too long for the model's "
                         "dynamics (%s)",
                         t, taken - taken_mark, t - t_mark, mean, t_end - t, t_end - times[0],
                         mean > 0.0 ? (t_end - t) / mean : HUGE_VAL, max_steps, method_name);
                status = @UPPER@_STEP_TOO_SMALL;
                break;
            }
            taken_mark = taken, t_mark = t;
        }
        /* no step passes the next output time: every output time ends a step, so an input that changes between
         * two of them (a square wave's edge, a table's corner) cannot be stepped over unseen */
        const double stop = times[out], remaining = stop - t, h_wanted = h;
        if (h >= (1.0 - 1e-6) * remaining || t + h >= stop) h = remaining; /* never a sliver short of it */
        /* the floor: what floating point resolves at t, and near t = 0 a thousandth of the span, but never more
         * than 1e-3 s of it (a horizon of 1e300 s must not make a step of 1e-7 s "too small") */
        if (!(h > 16.0 * DBL_EPSILON * fmax(fabs(t), 1e-3 * fmin(hmax, 1.0)))) {
            snprintf(m->message, sizeof m->message,
                     "t = %.9g s: the step fell to %.3g s; the rates are discontinuous or not finite here (%s)", t, h,
                     method_name);
            status = @UPPER@_STEP_TOO_SMALL;
            break;
        }
        if (explicit_method) {
            @NAME@_dopri5(m, t, h, err);
        } else {
            if (!have_jacobian) {
                @NAME@_call(m, @NAME@_jac, &t, m->z, m->jac);
                @NAME@_call(m, @NAME@_dfdt, &t, m->z, m->dfdt);
                m->jacobians += 1;
                have_jacobian = 1;
            }
            if (method == @UPPER@_RODAS3 ? @NAME@_rodas3(m, t, h, err) : @NAME@_ros23(m, t, h, err)) {
                h *= 0.25;
                m->rejected += 1;
                rejected_last = 1;
                event_step = 0;
                continue;
            }
        }
        taken += 1;
#if @UPPER@_N_SWITCHES > 0
        if (events && !event_step && @NAME@_not_finite(m->z_new) < 0) {
            /* an event: a kink or a jump of the equations inside the step. The step is taken again to end just
             * past it, before its error is judged (a step across a jump fails its error test, and so would its
             * shorter successors until one ends at the jump); after it, control goes on from the short step. */
            const double t_try = (h == t_end - t) ? t_end : t + h;
            double t_cross = t_try;
            if (@NAME@_crossing(m, t, h, t_try, &t_cross) && t_cross < t + (1.0 - 1e-6) * h) {
                h_resume = h;
                h = (t_cross - t) * (1.0 + 1e-9) + 64.0 * DBL_EPSILON * fmax(fabs(t), 1.0);
                event_step = 1;
                continue;
            }
        }
#endif
        double size = @NAME@_not_finite(m->z_new) >= 0 || @NAME@_not_finite(m->f1) >= 0
                          ? HUGE_VAL
                          : @NAME@_error_norm(err, m->z, m->z_new, rtol, atol);
        if (size > 1.0) {
            m->rejected += 1;
            h *= size == HUGE_VAL ? 0.25 : fmax(0.2, 0.9 * pow(size, -exponent));
            rejected_last = 1;
            event_step = 0; /* a step taken again to end past a kink failed: shorter steps will reach it */
            continue;
        }
        if (@NAME@_algebraic(m, t + h, m->z_new)) {
            status = @UPPER@_ALGEBRAIC;
            break;
        }
        const int landed = h == remaining;
        const double t1 = landed ? stop : t + h;
#if @UPPER@_N_SWITCHES > 0
        @NAME@_switches(m, t1, m->z_new, m->g1);
        for (int i = 0; i < @UPPER@_N_SWITCHES; ++i) {
            int now = @NAME@_side(m->g1[i], i);
            if (now != 0) m->side[i] = (signed char)now;
        }
#endif
        /* accepted: the step ends at the next output time (or short of it), so what it records is its end: that
         * output time and those a hair after it (closer together than a step can be: 1e-12 of the span) */
        for (; out < n_times && times[out] <= t1 + same_time; ++out) {
            @NAME@_record(m, out, times[out], m->z_new, states, outputs);
        }
        m->accepted += 1;
        memcpy(m->z, m->z_new, sizeof(double) * (size_t)n);
        memcpy(m->f0, m->f1, sizeof(double) * (size_t)n);
        t = t1;
        have_jacobian = 0;
        double grow = size <= 0.0 ? 5.0 : fmin(5.0, fmax(0.2, 0.9 * pow(size, -exponent)));
        const int after_rejection = rejected_last;
        if (rejected_last) grow = fmin(grow, 1.0);
        rejected_last = 0;
        if (event_step) { /* past the kink: the dynamics there are new, so control starts from the short step */
            m->events += 1;
            event_step = 0;
            h = fmin(fmin(h * grow, h_resume), hmax);
        } else if (landed && !after_rejection) { /* shortened to land on an output time: not a reason to slow */
            h = fmin(fmax(h * grow, h_wanted), hmax);
        } else {
            h = fmin(h * grow, hmax);
        }
    }
    m->t_start = t, m->steps = 0; /* the fixed-step API goes on from here */
    m->history = m->factorised = m->outputs_current = 0;
    if (status == @UPPER@_OK) m->message[0] = '\0';
    return status;
}

void @NAME@_integration_statistics(const @NAME@_instance *m, long long *accepted, long long *rejected,
                                   long long *evaluations, long long *jacobians, long long *events) {
    if (events != NULL) *events = m->events;
    if (accepted != NULL) *accepted = m->accepted;
    if (rejected != NULL) *rejected = m->rejected;
    if (evaluations != NULL) *evaluations = m->evaluations;
    if (jacobians != NULL) *jacobians = m->jacobians;
}

int @NAME@_step(@NAME@_instance *m) {
    const int n = @UPPER@_N_STATES;
    const double t1 = @NAME@_now(m, m->steps + 1);
    int status = @NAME@_advance(m);
    if (status) return status;
    int bad = @NAME@_not_finite(m->z_new);
    if (bad >= 0) {
        snprintf(m->message, sizeof m->message,
                 "t = %.9g s: the state %s became %g; the step %.6g s is too long for the model's fastest "
                 "dynamics here (@METHOD@), or the model diverges",
                 t1, @NAME@_state_names[bad], m->z_new[bad] * @NAME@_nominal[bad], @UPPER@_STEP);
        return @UPPER@_NOT_FINITE;
    }
    status = @NAME@_algebraic(m, t1, m->z_new);
    if (status) return status;
    memcpy(m->z_prev, m->z, sizeof(double) * (size_t)n);
    memcpy(m->z, m->z_new, sizeof(double) * (size_t)n);
    m->history = 1;
    m->steps += 1;
    m->outputs_current = 0;
    m->message[0] = '\0';
    return @UPPER@_OK;
}

int @NAME@_run(@NAME@_instance *m, long n, const double *inputs, double *states, double *outputs) {
    for (long k = 0; k < n; ++k) {
        if (inputs != NULL) {
            for (int j = 0; j < @UPPER@_N_INPUTS; ++j) @NAME@_set_input(m, j, inputs[k * @UPPER@_N_INPUTS + j]);
        }
        if (m->stop != NULL && *m->stop) {
            snprintf(m->message, sizeof m->message, "t = %.9g s: interrupted (the host's stop flag was set)",
                     @NAME@_now(m, m->steps));
            return @UPPER@_INTERRUPTED;
        }
        int status = @NAME@_step(m);
        if (status) return status;
        if (states != NULL) {
            for (int i = 0; i < @UPPER@_N_STATES; ++i) states[k * @UPPER@_N_STATES + i] = m->z[i] * @NAME@_nominal[i];
        }
        if (outputs != NULL) {
            for (int j = 0; j < @UPPER@_N_OUTPUTS; ++j) outputs[k * @UPPER@_N_OUTPUTS + j] = @NAME@_get_output(m, j);
        }
    }
    return @UPPER@_OK;
}

size_t @NAME@_instance_size(void) {
    return sizeof(@NAME@_instance);
}

@NAME@_instance *@NAME@_init(void *memory) {
    @NAME@_instance *m = (@NAME@_instance *)memory;
    if (m == NULL) return NULL;
    memset(m, 0, sizeof *m);
    for (int i = 0; i < @UPPER@_N_PARAMETERS; ++i) m->p[i] = @NAME@_parameter_defaults[i];
    m->q_current = 0;
    @NAME@_reset(m);
    return m;
}

@NAME@_instance *@NAME@_new(void) {
    return @NAME@_init(malloc(sizeof(@NAME@_instance)));
}

void @NAME@_set_stop(@NAME@_instance *m, const volatile int *flag) {
    m->stop = flag;
}

void @NAME@_free(@NAME@_instance *m) {
    free(m);
}

void @NAME@_reset(@NAME@_instance *m) {
    @NAME@_call(m, @NAME@_z0, NULL, NULL, m->z);
    m->steps = m->iterations = m->jacobians = 0;
    m->accepted = m->rejected = m->evaluations = m->events = 0;
    m->t_start = 0.0;
    m->history = m->factorised = m->outputs_current = 0;
    m->message[0] = '\0';
}

int @NAME@_set_parameter(@NAME@_instance *m, int index, double value) {
    if (index < 0 || index >= @UPPER@_N_PARAMETERS) return -1;
    m->p[index] = value;
    m->factorised = m->outputs_current = m->q_current = 0;
    return 0;
}

void @NAME@_set_parameters(@NAME@_instance *m, const double *values) {
    for (int i = 0; i < @UPPER@_N_PARAMETERS; ++i) m->p[i] = values[i];
    m->factorised = m->outputs_current = m->q_current = 0;
}

void @NAME@_set_states(@NAME@_instance *m, const double *x) {
    for (int i = 0; i < @UPPER@_N_STATES; ++i) m->z[i] = x[i] / @NAME@_nominal[i];
    m->history = m->outputs_current = 0;
}

double @NAME@_get_parameter(const @NAME@_instance *m, int index) {
    return index >= 0 && index < @UPPER@_N_PARAMETERS ? m->p[index] : NAN;
}

int @NAME@_set_input(@NAME@_instance *m, int index, double value) {
    if (index < 0 || index >= @UPPER@_N_INPUTS) return -1;
    m->p[@UPPER@_N_PARAMETERS + index] = value;
    m->outputs_current = m->q_current = 0;
    return 0;
}

double @NAME@_get_input(const @NAME@_instance *m, int index) {
    return index >= 0 && index < @UPPER@_N_INPUTS ? m->p[@UPPER@_N_PARAMETERS + index] : NAN;
}

int @NAME@_set_state(@NAME@_instance *m, int index, double value) {
    if (index < 0 || index >= @UPPER@_N_STATES) return -1;
    m->z[index] = value / @NAME@_nominal[index];
    m->history = m->outputs_current = 0;
    return 0;
}

double @NAME@_get_state(const @NAME@_instance *m, int index) {
    return index >= 0 && index < @UPPER@_N_STATES ? m->z[index] * @NAME@_nominal[index] : NAN;
}

double @NAME@_get_output(@NAME@_instance *m, int index) {
    if (index < 0 || index >= @UPPER@_N_OUTPUTS) return NAN;
    if (!m->outputs_current) {
        double t = @NAME@_now(m, m->steps);
        @NAME@_call(m, @NAME@_y, &t, m->z, m->y);
        m->outputs_current = 1;
    }
    return m->y[index];
}

/* The host's states x in m->z_host, scaled. */
static const double *@NAME@_scaled(@NAME@_instance *m, const double *x) {
    for (int i = 0; i < @UPPER@_N_STATES; ++i) m->z_host[i] = x[i] / @NAME@_nominal[i];
    return m->z_host;
}

void @NAME@_initial_states(@NAME@_instance *m, double *x) {
    @NAME@_call(m, @NAME@_z0, NULL, NULL, m->z_host);
    for (int i = 0; i < @UPPER@_N_STATES; ++i) x[i] = m->z_host[i] * @NAME@_nominal[i];
}

int @NAME@_rates(@NAME@_instance *m, double t, const double *x, double *dxdt) {
    @NAME@_rates_scaled(m, t, @NAME@_scaled(m, x), dxdt);
    for (int i = 0; i < @UPPER@_N_STATES; ++i) {
        dxdt[i] *= @NAME@_nominal[i];
        if (!isfinite(dxdt[i])) {
            snprintf(m->message, sizeof m->message, "t = %.9g s: the rate of the state %s is %g", t,
                     @NAME@_state_names[i], dxdt[i]);
            return @UPPER@_NOT_FINITE;
        }
    }
    return @UPPER@_OK;
}

void @NAME@_outputs(@NAME@_instance *m, double t, const double *x, double *y) {
    @NAME@_call(m, @NAME@_y, &t, @NAME@_scaled(m, x), y);
}

int @NAME@_check(@NAME@_instance *m, double t, const double *x) {
    const double *z = @NAME@_scaled(m, x);
    int bad = @NAME@_not_finite(z);
    if (bad >= 0) {
        snprintf(m->message, sizeof m->message, "t = %.9g s: the state %s is %g", t, @NAME@_state_names[bad], x[bad]);
        return @UPPER@_NOT_FINITE;
    }
    return @NAME@_algebraic(m, t, z);
}

double @NAME@_state_nominal(int index) {
    return index >= 0 && index < @UPPER@_N_STATES ? @NAME@_nominal[index] : NAN;
}

double @NAME@_time(const @NAME@_instance *m) {
    return @NAME@_now(m, m->steps);
}

const char *@NAME@_message(const @NAME@_instance *m) {
    return m->message;
}

void @NAME@_statistics(const @NAME@_instance *m, long long *steps, long long *iterations, long long *jacobians) {
    if (steps != NULL) *steps = m->steps;
    if (iterations != NULL) *iterations = m->iterations;
    if (jacobians != NULL) *jacobians = m->jacobians;
}

int @NAME@_find(const char *const *names, const char *name) {
    for (int i = 0; names != NULL && name != NULL && names[i] != NULL; ++i) {
        if (strcmp(names[i], name) == 0) return i;
    }
    return -1;
}
