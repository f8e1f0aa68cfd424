"""The integrator driver of a simulation (beyond the paper; docs/simulation.md,
"Method", "Events" and "Outputs").

:class:`Simulation` integrates the exact equations of motion (those of the
body model, :mod:`deathsphere.simulation.bodies`: the paper's
:mod:`deathsphere.physics.dynamics`, or a machine's eqs. M16-M19) for all bodies of a :class:`Starts` at
once (one state vector of 9 n rows, one vectorised right-hand side) with
:func:`scipy.integrate.solve_ivp` (through :func:`deathsphere.simulation.integrator.integrate`),
period by period (:meth:`Simulation.chunks`),
stopping a body at the terminal events of
:mod:`deathsphere.simulation.events`; :func:`simulate` runs it to the end.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator

import numpy as np

from deathsphere.params import RTOL_MIN
from deathsphere.physics import dynamics as dyn
from deathsphere.simulation.bodies import ON_GROUND, model_of, take
from deathsphere.simulation.events import EVENT_STATUSES, EVENT_TOL, stopped_at_start
from deathsphere.simulation.integrator import integrate
from deathsphere.simulation.series import (
    concat_tables,
    rows_table,
    sample_quantities,
    series_columns,
    series_rows,
)
from deathsphere.simulation.starts import Starts
from deathsphere.simulation.status import RunStatus, failed_reason
from deathsphere.simulation.summary import Ledger
from deathsphere.table import Table

__all__ = ["METHODS", "FRAMES", "DEFAULT_MAX_STEPS", "SPIN_RATIO_MAX", "Simulation", "run_simulation"]

#: solve_ivp methods accepted.  The explicit Runge-Kutta methods are the
#: natural choice (the flow is not stiff); Radau/BDF get a block-diagonal
#: Jacobian sparsity pattern (bodies are independent).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")
#: explicit Runge-Kutta methods: they never use a vectorised right-hand side
#: (vectorized=True only made solve_ivp pass (9 n, 1) arrays)
_EXPLICIT = ("DOP853", "RK45", "RK23")
#: Frames the state is integrated in: "turning" (about the vertical at the
#: steady orbit's rate Omega, where a steady horizontal orbit is a fixed
#: point; vertical orbits are always integrated in the lab) or "lab".
FRAMES = ("turning", "lab")

#: internal samples per period at least (phi is unwrapped on them, extrema
#: are taken over them); output rows are every m-th of them.
_MIN_INTERNAL_PER_PERIOD = 16
#: largest step, in units of 1/S (S = sqrt(|w|^2 + Omega^2 + g/a), the rate
#: scale of the body): keeps the nutation (frequencies ~ S) resolved when
#: the error estimate alone would allow huge steps (docs/simulation.md)
_MAX_STEP_RATES = 2.0
#: absolute tolerance on a sphere's axis-1 marker rows (no error control)
_MARKER_ATOL = 1e3
#: the step budget of a run unless told otherwise (``max_steps``): about a
#: minute or two for one body.  The steps are at least the run's length
#: times S / 2 (the cap above), so a body spinning far faster than it orbits
#: (a/r small) needs millions of steps per period; such a run is refused
#: before it starts, with its estimate (docs/simulation.md, "Cost").
DEFAULT_MAX_STEPS = 1_000_000
#: the largest spin ratio S T / (2 pi) (S as above, T the period) that is
#: integrated at all.  The state holds the fast spin and the slow orbital
#: motion in the same Cartesian components, so round-off in the spin
#: (eps S) reaches the slow motion at a relative eps times this ratio: at
#: 1e7 that is ~2e-9, beyond it the orbit drifts visibly from round-off
#: alone and at a/r ~ 1e-18 the start state itself is lost.  Not a budget:
#: max_steps does not lift it.
SPIN_RATIO_MAX = 1e7
#: the most steps one solve_ivp call is expected to take (from the cap
#: 2 / S): longer periods are split into pieces, because solve_ivp keeps
#: every step of a call (its dense output and states) until it returns, so
#: memory would otherwise grow with the step count; the pieces also pace
#: the progress callback.
_STEPS_PER_CALL = 20_000


def _jac_sparsity(nA):
    """Block-diagonal sparsity of the Jacobian (bodies are independent)
    in the component-major state layout (row = component * nA + body)."""
    from scipy.sparse import coo_matrix

    comp = np.arange(9)
    body = np.arange(nA)
    rows = (comp[:, None, None] * nA + body[None, None, :])
    cols = (comp[None, :, None] * nA + body[None, None, :])
    rows, cols = np.broadcast_arrays(rows, cols)
    data = np.ones(rows.size)
    return coo_matrix((data, (rows.ravel(), cols.ravel())), shape=(9 * nA, 9 * nA)).tocsr()


class Simulation:
    """Integrate the exact equations of motion for a set of bodies (beyond
    the paper; docs/simulation.md).

    Parameters
    ----------
    starts : :class:`Starts` (from :func:`horizontal_starts`,
        :func:`vertical_starts`, :meth:`Starts.concat`)
    periods : float > 0   run length in periods of each body's orbit
        (:attr:`Starts.period`): body i runs for ``periods * period_i``
    points_per_period : int >= 1   output rows per period of the fastest body
        (all bodies share one time grid, dt = min(period) / points_per_period)
    method : one of :data:`METHODS` (solve_ivp), default DOP853
    rtol : float   solve_ivp's relative tolerance (default 1e-10)
    atol : float or None   dimensionless absolute tolerance, scaled per state
        component: atol * r on the centre [m], atol on axis 1 [-] (not
        controlled for a sphere, where axis 1 is a marker), atol * S on the
        angular velocity [rad/s], S = sqrt(|w|^2 + Omega^2 + g/a) at t = 0.
        Default: equal to rtol.  The step is also capped at 2 / max(S), so
        the nutation stays resolved where the error estimate alone would
        allow huge steps (a steady orbit in the turning frame).
    frame : "turning" (default) or "lab", see :data:`FRAMES`
    mu : float, array or None   friction available (None: ``starts.mu``,
        from the Setup); inf: no ``slips`` event
    project_each_period : bool   move the state back onto the constraints
        (:func:`deathsphere.physics.dynamics.project`) at every chunk
        boundary; off by default, so ``constraint_residual`` shows the
        integrator's true drift
    record_states : bool   also keep the full state (c, e1, w) at every
        output row, for :meth:`sample_states` (off by default: the time
        series and summary are the same either way)
    max_steps : int >= 1   the step budget (default :data:`DEFAULT_MAX_STEPS`):
        a run whose estimate :attr:`estimated_steps` exceeds it is refused
        (ValueError) before anything is integrated.  Bodies whose spin
        ratio exceeds :data:`SPIN_RATIO_MAX` are refused whatever the budget.

    Iterate with :meth:`chunks` (streaming), then :meth:`summary`; or call
    :meth:`run`.
    """

    def __init__(self, starts: Starts, *, periods: float = 20.0, points_per_period: int = 100,
                 method: str = "DOP853", rtol: float = 1e-10, atol: float | None = None,
                 frame: str = "turning", mu=None, project_each_period: bool = False,
                 record_states: bool = False, max_steps: int = DEFAULT_MAX_STEPS):
        if not (isinstance(periods, (int, float, np.integer, np.floating)) and math.isfinite(periods)
                and periods > 0):
            raise ValueError(f"periods must be a finite number > 0 (got {periods!r})")
        if isinstance(points_per_period, bool) or int(points_per_period) != points_per_period \
                or points_per_period < 1:
            raise ValueError(f"points_per_period must be an integer >= 1 (got {points_per_period!r})")
        if method not in METHODS:
            raise ValueError(f"method must be one of {' | '.join(METHODS)} (got {method!r})")
        if not (math.isfinite(rtol) and RTOL_MIN <= rtol < 1):
            # solve_ivp would raise a smaller rtol to 100 eps behind the caller's back
            raise ValueError(f"rtol must be within {RTOL_MIN:.3g} (100 eps, the least solve_ivp honours)..1 "
                             f"(got {rtol!r})")
        atol = rtol if atol is None else atol
        if not (math.isfinite(atol) and atol > 0):
            raise ValueError(f"atol must be > 0 (got {atol!r})")
        if frame not in FRAMES:
            raise ValueError(f"frame must be one of {' | '.join(FRAMES)} (got {frame!r})")
        if len(starts) == 0:
            raise ValueError("no bodies to simulate")
        if isinstance(max_steps, bool) or int(max_steps) != max_steps or max_steps < 1:
            raise ValueError(f"max_steps must be an integer >= 1 (got {max_steps!r})")
        mu_arr = starts.mu if mu is None else np.broadcast_to(np.asarray(mu, dtype=float), (len(starts),))
        if np.any(np.isnan(mu_arr)) or np.any(mu_arr < 0):
            raise ValueError("mu must be >= 0 (inf: no limit)")
        self.starts = starts
        #: what rolls: the paper's bodies or machines (simulation.bodies)
        self.model = model_of(starts.params)
        self.periods = float(periods)
        self.points_per_period = int(points_per_period)
        self.method = method
        self.rtol = float(rtol)
        self.atol = float(atol)
        self.frame = frame
        self.mu = np.array(mu_arr, dtype=float)
        self.project_each_period = bool(project_each_period)
        ok = starts.pending
        self._ok = ok
        self.t_ref = float(np.min(starts.period[ok])) if ok.any() else 1.0
        self.oversample = -(-_MIN_INTERNAL_PER_PERIOD // self.points_per_period)   # ceil
        self.dt = self.t_ref / (self.points_per_period * self.oversample)
        self.t_end = np.where(ok, self.periods * np.where(ok, starts.period, 0.0), 0.0)
        self.j_max = int(math.ceil(float(np.max(self.t_end)) / self.dt - 1e-9)) if ok.any() else 0
        ends = np.unique(self.t_end[ok])
        if self.j_max and ends.size == 1:
            # the grid ends exactly at the (common) end time: 0.999 periods
            # are 0.999, not the 0.99 of the sample before, and 0.001 periods
            # are run rather than rounded to none
            self.dt = float(ends[0]) / self.j_max
        self.j_per_chunk = self.points_per_period * self.oversample
        self._tol = 1e-9 * self.dt
        self._frame_rate = np.where(frame == "turning", starts.turning, 0.0).astype(float)
        self._summary = None
        self.record_states = bool(record_states)
        self._state_parts = []
        self.max_steps = int(max_steps)
        # the same rate scale S as the step cap of _solve, per body at t = 0
        w0 = starts.state[dyn.W]
        with np.errstate(invalid="ignore"):
            scale = np.sqrt(np.sum(w0 * w0, axis=0) + starts.rate ** 2 + starts.params.g / starts.params.a)
        self._rate_scale = np.where(ok, scale, 0.0)
        #: fast radians per radian of orbit, S T / (2 pi), per body (0 if not integrated)
        self.spin_ratio = np.where(ok, self._rate_scale * np.where(ok, starts.period, 0.0) / (2 * np.pi), 0.0)
        s_max = float(np.max(self._rate_scale)) if ok.any() else 0.0
        #: least number of steps the run takes: its length over the step cap 2 / S
        #: (error control may ask for more, never fewer)
        self.estimated_steps = int(math.ceil(float(np.max(self.t_end)) * s_max / _MAX_STEP_RATES)) if ok.any() else 0
        chunk_steps = self.j_per_chunk * self.dt * s_max / _MAX_STEP_RATES
        self.pieces_per_chunk = max(1, int(math.ceil(chunk_steps / _STEPS_PER_CALL)))
        self._check_cost()

    @property
    def ground(self):
        """The ground record of a run off the globe (docs/simulation.md, "On
        any ground"), None in the globe."""
        return self.starts.params.ground if getattr(self.model, "off_globe", False) else None

    @property
    def n_chunks(self) -> int:
        """Number of chunks :meth:`chunks` yields (one per period of the
        fastest body)."""
        return max(1, -(-self.j_max // self.j_per_chunk))

    @property
    def n_progress(self) -> int:
        """The ``total`` :meth:`chunks` passes to its progress callback: the
        chunks, each split into :attr:`pieces_per_chunk` pieces (one piece
        per chunk unless a period takes many steps)."""
        return self.n_chunks * self.pieces_per_chunk

    def _check_cost(self):
        """Refuse, before any work, a run float64 cannot integrate faithfully
        (:data:`SPIN_RATIO_MAX`) or one over the step budget."""
        if not self._ok.any():
            return
        worst = int(np.argmax(self.spin_ratio))
        ratio = float(self.spin_ratio[worst])
        if ratio > SPIN_RATIO_MAX:
            p = self.starts.params
            # the ratio goes as r / a: the a/r at which it would be allowed
            a_r = float(p.a[worst] / p.r[worst]) * ratio / SPIN_RATIO_MAX
            raise ValueError(
                f"cannot simulate: the body spins {ratio:.2g} radians per radian of orbit, more than the "
                f"{SPIN_RATIO_MAX:.0e} float64 can integrate faithfully (the slow orbital motion would be lost "
                f"in the round-off of the spin); use a/r >= {a_r:.1g} (or a slower spin)")
        if self.estimated_steps > self.max_steps:
            cost = self._step_cost()
            raise ValueError(
                f"simulate would take at least {self.estimated_steps:.2g} steps (the body spins "
                f"{ratio:.2g} radians per radian of orbit and every step must resolve that), about "
                f"{_duration(self.estimated_steps * cost)} at the {cost * 1e6:.0f} us per step measured here; "
                f"the budget is max_steps = {self.max_steps:.2g}: raise it (--max-steps) or run fewer periods")

    def _step_cost(self) -> float:
        """Seconds per step, measured on a short run of these bodies (only
        ever called to word a refusal)."""
        active = np.flatnonzero(self._ok)
        y = self.starts.state[:, active]
        span = 200 * _MAX_STEP_RATES / float(np.max(self._rate_scale[active]))
        wall0 = time.perf_counter()
        done, _ = self._solve(active, y, 0.0, span)
        return (time.perf_counter() - wall0) / max(len(done.sol.t) - 1, 1)

    # ---- samples and rows -------------------------------------------------------

    def _sample(self, idx, y, t, ledger):
        """:func:`sample_quantities` of bodies ``idx`` at states y (9, m, nb), times t (m,)."""
        return sample_quantities(self.starts, idx, y, t, self._frame_rate, ledger.phi_carry, ledger.e0,
                                 ledger.e_scale, with_state=self.record_states)

    def _rows(self, idx, t, q, keep):
        """Series rows of the samples where keep (m, nb); with
        ``record_states`` the states of those rows are kept too."""
        rows = self.starts.input_row[idx]
        if "state" in q:
            self._state_parts.append({
                "input_row": np.broadcast_to(rows[None, :], keep.shape)[keep].astype(np.int64),
                "t_s": np.broadcast_to(t[:, None], keep.shape)[keep],
                "state": q["state"][:, keep]})
        return series_rows(rows, t, q, keep, self.model.series_extras)

    # ---- the run ----------------------------------------------------------------

    def chunks(self, progress: Callable[[int, int], None] | None = None) -> Iterator[Table]:
        """Run the simulation, yielding the time series chunk by chunk.

        Each chunk is a :class:`Table` with columns
        :data:`~deathsphere.simulation.series.SERIES_COLUMNS` covering one
        period of the fastest body (the first also holds t = 0); rows are
        time-major (all bodies at one time, by ``input_row``); a body's rows
        stop at its end time or at its event (the event itself is its last
        row).  ``progress(done, total)`` is called after each chunk with
        counts of chunks (total = :attr:`n_chunks`).  Once the generator is
        exhausted :meth:`summary` is available.  Each call runs the
        simulation afresh.
        """
        s = self.starts
        wall0 = time.perf_counter()
        self._summary = None
        self._state_parts = []
        ledger = Ledger(s)
        active, y, rows = self._start(ledger)
        t_cur = 0.0
        total = self.n_progress
        pieces = self.pieces_per_chunk
        for chunk in range(self.n_chunks):
            j0 = chunk * self.j_per_chunk
            j1 = min((chunk + 1) * self.j_per_chunk, self.j_max)
            t_b = j1 * self.dt
            if self.project_each_period and active.size and chunk > 0:
                y = self.model.project(y, take(s.params, active))
            for piece in range(1, pieces + 1):
                t_p = t_b if piece == pieces else (j0 + (j1 - j0) * piece / pieces) * self.dt
                while active.size and t_cur < t_p:
                    active, y, t_cur = self._integrate(active, y, t_cur, t_p, j0, j1, ledger, rows)
                if progress is not None and piece < pieces and active.size:
                    progress(chunk * pieces + piece, total)
            done = self.t_end[active] <= t_b + self._tol
            for i in active[done]:
                ledger.finish(i, RunStatus.COMPLETED)
            active, y = active[~done], y[:, ~done]
            yield rows_table(rows, series_columns(self.model))
            rows = []
            if progress is not None:
                progress((chunk + 1) * pieces, total)
            if not active.size:
                if progress is not None and (chunk + 1) * pieces < total:
                    progress(total, total)
                break
        for i in active:          # only if rounding left a body a hair short of its end
            ledger.finish(i, RunStatus.COMPLETED)
        self._summary = ledger.table(mu=self.mu, method=self.method, rtol=self.rtol, atol=self.atol,
                                     frame=self.frame, wall=time.perf_counter() - wall0)

    def _start(self, ledger):
        """t = 0: every body's first row; bodies without contact (or
        slipping) at the start stop there.  Returns the bodies that go on,
        their state (9, nA) and the row blocks so far."""
        active = np.flatnonzero(self._ok)
        y = self.starts.state[:, active].copy()                       # (9, nA)
        rows = []
        if active.size:
            zero = np.zeros(1)
            q = self._sample(active, y[:, None, :], zero, ledger)
            everything = np.ones((1, active.size), dtype=bool)
            ledger.fold(active, q, everything)
            ledger.acc["t_done"][active] = 0.0
            rows.append(self._rows(active, zero, q, everything))
            lost, slip = stopped_at_start(q["normal"][-1], q["friction"][-1], self.mu[active])
            for flag, status in zip((lost, slip), EVENT_STATUSES):
                for j in np.flatnonzero(flag):
                    ledger.record_event(active[j], j, status, 0.0, q)
            keep = ~(lost | slip)
            active, y = active[keep], y[:, keep]
        return active, y, rows

    def _solve(self, active, y, t_cur, t_b):
        """One solve_ivp call (dense output, terminal events) for the bodies
        ``active`` at states y from t_cur to t_b, through the one driver
        (:func:`~deathsphere.simulation.integrator.integrate`).  Returns
        (:class:`~deathsphere.simulation.integrator.Solved`, the events)."""
        s = self.starts
        nA = active.size
        p = take(s.params, active)
        events = self.model.terminal_events(p, self.mu[active])
        fun = self.model.ode(p, self._frame_rate[active])
        w0 = s.state[dyn.W][:, active]
        scale_w = np.sqrt(np.sum(w0 * w0, axis=0) + s.rate[active] ** 2 + p.g / p.a)
        # a sphere's axis-1 rows are a body-fixed marker that does not enter
        # its dynamics: kept out of the error control (docs/simulation.md)
        marker = np.where(self.model.marker(p), _MARKER_ATOL / self.atol, 1.0)
        atol = self.atol * np.concatenate((np.broadcast_to(p.r, (3, nA)), np.broadcast_to(marker, (3, nA)),
                                           np.broadcast_to(scale_w, (3, nA)))).reshape(-1)
        # resolve the body's own rotation and nutation even where the state
        # barely moves (a steady orbit in the turning frame): h <= 2 / S
        options = {"max_step": _MAX_STEP_RATES / float(np.max(scale_w))}
        if self.method in ("Radau", "BDF") and nA > 1:
            options["jac_sparsity"] = _jac_sparsity(nA)
        # on a profile the steps stop at the spline's knots under the contacts
        kinks = self.model.kinks(p) if hasattr(self.model, "kinks") else None
        done = integrate(fun, (t_cur, t_b), y.reshape(-1), events, method=self.method, rtol=self.rtol, atol=atol,
                         dense_output=True, vectorized=self.method not in _EXPLICIT, kinks=kinks, **options)
        return done, events

    def _integrate(self, active, y, t_cur, t_b, j0, j1, ledger, rows):
        """One solve_ivp call for the bodies ``active`` from t_cur to t_b or
        to the first terminal event; samples the dense output on the grid.
        Returns the bodies still running, their state and the time reached."""
        nA = active.size
        done, events = self._solve(active, y, t_cur, t_b)
        sol = done.sol
        ledger.n_steps += max(len(sol.t) - 1, 0)
        ledger.n_fev += int(sol.nfev)
        t_stop = float(sol.t[-1])
        self._sample_grid(active, sol, t_cur, t_stop, j0, j1, ledger, rows)
        if sol.status == -1:
            for i in active:
                ledger.finish(i, RunStatus.FAILED, failed_reason(sol.message))
                ledger.acc["event_t"][i] = t_stop
            return active[:0], y[:, :0], t_b
        if sol.status != 1:
            return active, sol.y[:, -1].reshape(9, nA), t_b
        return self._stop_at_event(active, done, events, ledger, rows)

    def _sample_grid(self, active, sol, t_cur, t_stop, j0, j1, ledger, rows):
        """Sample the dense output ``sol`` on the grid points j0 < j <= j1
        within (t_cur, t_stop]; fold them into the summary and keep the
        output rows (every ``oversample``-th, and the last)."""
        nA = active.size
        end = self.t_end[active] + self._tol
        j_lo = max(j0 + 1, int(math.floor(t_cur / self.dt + 1e-9)) + 1)
        js = np.arange(j_lo, j1 + 1)
        ts = js * self.dt
        sel = ts <= t_stop + self._tol
        js, ts = js[sel], np.minimum(ts[sel], t_stop)
        if not ts.size:
            return
        ys = sol.sol(ts).reshape(9, nA, ts.size).transpose(0, 2, 1)   # (9, m, nA)
        q = self._sample(active, ys, ts, ledger)
        within = ts[:, None] <= end[None, :]
        ledger.fold(active, q, within)
        keep = within & ((js % self.oversample == 0) | (js == self.j_max))[:, None]
        if keep.any():
            rows.append(self._rows(active, ts, q, keep))
        n_in = within.sum(axis=0)
        has = n_in > 0
        ledger.acc["t_done"][active[has]] = ts[n_in[has] - 1]

    def _stop_at_event(self, active, done, events, ledger, rows):
        """After a terminal event: stop every body whose event value reached
        zero there (the one that fired, and any within :data:`EVENT_TOL`);
        an event after a body's end time completes it instead.  Returns the
        bodies still running, their state and the event time."""
        nA = active.size
        end = self.t_end[active] + self._tol
        k_fired, t_ev = done.k_event, done.t_event
        y_ev = done.y_event.reshape(9, nA)
        vals = events.values(t_ev, y_ev.reshape(-1))
        q = self._sample(active, y_ev[:, None, :], np.array([t_ev]), ledger)
        in_time = t_ev <= end
        ledger.fold(active, q, in_time[None, :])
        stopped = np.zeros(nA, dtype=bool)
        for k_ev, event in enumerate(events):
            v, status = vals[k_ev], event.status
            hit = (v <= EVENT_TOL) & ~stopped
            if k_ev == k_fired:
                hit[np.argmin(v)] = True
            for j in np.flatnonzero(hit):
                stopped[j] = True
                if in_time[j]:
                    ledger.record_event(active[j], j, status, t_ev, q)
                else:   # the event came after the body's end time
                    ledger.finish(active[j], RunStatus.COMPLETED)
        emit = (stopped & in_time)[None, :]
        if emit.any():
            rows.append(self._rows(active, np.array([t_ev]), q, emit))
        return active[~stopped], y_ev[:, ~stopped], t_ev

    def summary(self) -> Table:
        """One row per body (:data:`~deathsphere.simulation.summary.SUMMARY_COLUMNS`); available once
        :meth:`chunks` has been exhausted (RuntimeError before)."""
        if self._summary is None:
            raise RuntimeError("the simulation has not been run to the end: exhaust chunks() or call run()")
        return self._summary

    def sample_states(self) -> dict:
        """The full state at every output row (beyond the paper;
        docs/simulation.md "3-D view"), for a run made with
        ``record_states=True``, once :meth:`chunks` has been exhausted.

        Returns a dict: ``input_row`` (N,), ``t_s`` (N,) and ``state`` (9, N),
        the state (c, e1, w) of :mod:`deathsphere.physics.dynamics` in lab
        components (a run in the turning frame is rotated back by Omega t),
        the rows in the order of the time series (time-major, then
        ``input_row``), so row j belongs to row j of the series.
        """
        if not self.record_states:
            raise RuntimeError("the simulation was made without record_states=True")
        self.summary()
        parts = self._state_parts
        if not parts:
            return {"input_row": np.zeros(0, dtype=np.int64), "t_s": np.zeros(0), "state": np.zeros((9, 0))}
        rows = np.concatenate([p["input_row"] for p in parts])
        t = np.concatenate([p["t_s"] for p in parts])
        state = np.concatenate([p["state"] for p in parts], axis=1)
        order = np.lexsort((rows, t))
        return {"input_row": rows[order], "t_s": t[order], "state": state[:, order]}

    def view_frames(self) -> dict[int, dict]:
        """What the 3-D view draws of each body at every output row
        (:func:`deathsphere.simulation.frames.body_frames`), for a run made
        with ``record_states=True``, once :meth:`chunks` has been exhausted."""
        from deathsphere.simulation.frames import body_frames

        return body_frames(self.summary(), self.sample_states(), params=self.starts.params)

    def run(self, progress: Callable[[int, int], None] | None = None) -> tuple[Table, Table]:
        """Run to the end; returns ``(series, summary)``."""
        series = concat_tables(list(self.chunks(progress)))
        return series, self.summary()


def _duration(seconds: float) -> str:
    """A rough duration in words: '40 s', '7 min', '3.2 h', '12 days'."""
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    if seconds < 172800:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.2g} days"


def run_simulation(starts: Starts, progress: Callable[[int, int], None] | None = None,
             **options) -> tuple[Table, Table]:
    """``Simulation(starts, **options).run(progress)``: the whole time series
    and the summary (beyond the paper; docs/simulation.md)."""
    return Simulation(starts, **options).run(progress)
