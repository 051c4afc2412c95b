"""Sunlit stretches (cityshade.sunhours.stretches): run lengths against the reference."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from reference import reference_stretches



# --- run lengths --------------------------------------------------------------------------------

def _units(order_of_step):
    """Units like plan_units: sun positions in first-occurrence order, -1 = below horizon."""
    units = {}
    for i, u in enumerate(order_of_step):
        if u >= 0:
            units.setdefault(u, []).append(i)
    return [SimpleNamespace(steps=tuple(units[k])) for k in sorted(units)]


def _run_and_check(st, units, lit_unit, n, longest, qualified):
    """Every unit's flags for ``n`` samples, in unit order: the reference's numbers."""
    st.plan(units, None, n)
    for k in range(len(units)):
        st.add(k, None, lit_unit[k])
    st.finish()
    assert np.array_equal(st.samples.longest_h, longest)
    assert np.array_equal(st.samples.qualified_h, qualified)


def test_stretches_match_the_reference_with_gaps_duplicates_and_resume():
    from cityshade.sunhours.stretches import Stretches

    rng = np.random.default_rng(7)
    n_steps, n = 40, 25
    starts, ends = [], []
    t = 1e9
    for i in range(n_steps):
        t += 1800.0 if rng.random() < 0.15 else 0.0  # a gap: another window or day
        starts.append(t)
        t += float(rng.choice([600.0, 300.0]))
        ends.append(t)
    # Sun positions in first-occurrence order; some steps share an earlier one (also far
    # apart), some have the sun down (-1).
    unit_of_step, n_units = [], 0
    for i in range(n_steps):
        r = rng.random()
        if r < 0.15:
            unit_of_step.append(-1)
        elif r < 0.3 and n_units:
            unit_of_step.append(int(rng.integers(n_units)))
        else:
            unit_of_step.append(n_units)
            n_units += 1
    units = _units(unit_of_step)
    lit_unit = rng.random((len(units), n)) < 0.6
    lit_steps = np.array([lit_unit[u] if u >= 0 else np.zeros(n, bool) for u in unit_of_step])
    longest, qualified = reference_stretches(lit_steps, starts, ends, min_stretch_h=0.4)
    assert longest.max() > 0.5 and 0 < (qualified > 0).sum() < n

    _run_and_check(Stretches(starts, ends, min_stretch_h=0.4), units, lit_unit, n, longest,
                   qualified)

    # Interrupted after unit 12 and restored from the saved state: the same numbers.
    a = Stretches(starts, ends, min_stretch_h=0.4)
    a.plan(units, None, n)
    for k in range(12):
        a.add(k, None, lit_unit[k])
    saved = {key: np.array(v) for key, v in a.state().items()}
    b = Stretches(starts, ends, min_stretch_h=0.4)
    b.plan(units, None, n)
    b.restore(saved)
    for k in range(12, len(units)):
        b.add(k, None, lit_unit[k])
    b.finish()
    assert np.array_equal(b.samples.longest_h, longest)
    assert np.array_equal(b.samples.qualified_h, qualified)


def test_a_night_of_steps_closes_the_stretches_once(monkeypatch):
    """Steps with the sun down close every stretch; the second and later of a night change
    nothing and are skipped (the same numbers as the reference, one close per night)."""
    import cityshade.sunhours.stretches as S

    n_steps, n = 30, 9
    starts = [1e9 + 600.0 * i for i in range(n_steps)]
    ends = [s + 600.0 for s in starts]
    down = set(range(8, 14)) | set(range(22, 30))            # two nights of steps
    unit_of_step, units = [], []
    for i in range(n_steps):
        unit_of_step.append(-1 if i in down else len(units))
        if i not in down:
            units.append(SimpleNamespace(steps=(i,)))
    lit_unit = np.random.default_rng(3).random((len(units), n)) < 0.7
    lit_steps = np.array([lit_unit[u] if u >= 0 else np.zeros(n, bool) for u in unit_of_step])
    longest, qualified = reference_stretches(lit_steps, starts, ends, min_stretch_h=0.5)
    calls = []
    real = S.close_stretches
    monkeypatch.setattr(S, "close_stretches", lambda *a: calls.append(1) or real(*a))
    _run_and_check(S.Stretches(starts, ends, min_stretch_h=0.5), units, lit_unit, n, longest,
                   qualified)
    assert len(calls) == 2        # one per night; the end of the run finds them closed


def test_stretch_kernels_by_hand():
    from cityshade.sunhours.stretches import close_stretches, update_stretches

    cur, lng, q = np.zeros(2), np.zeros(2), np.zeros(2)
    for lit in ([1, 0], [1, 1], [0, 1], [1, 1]):
        update_stretches(np.array(lit, np.uint8), 0.5, cur, lng, q, 0.75)
    close_stretches(cur, lng, q, 0.75)
    # receiver 0: 1.0 h then 0.5 h; receiver 1: 1.5 h.
    assert lng.tolist() == [1.0, 1.5] and q.tolist() == [1.0, 1.5] and cur.tolist() == [0, 0]
