"""pulab.fixedpoint.boxsearch: the box search both proofs run (order, budget, slices, leftovers)."""

from __future__ import annotations

from pulab.analyses.slices import finish
from pulab.fixedpoint.boxsearch import halve, search, volume


def _halving(seen: list, cost: int = 1):
    """A visit that records each box and halves every box wider than one point."""
    def visit(key, box, data):
        seen.append((box["x"], data))
        if box["x"][0] == box["x"][1]:
            return cost, ()
        return cost, [(-volume(h), h, data + 1) for h in halve(box, "x")]
    return visit


def test_largest_first_and_ties_in_the_order_made():
    seen = []
    work, left = finish(search({"x": (0, 7)}, -8, _halving(seen), budget=7, data=0))
    assert [b for b, _ in seen] == [(0, 7), (0, 3), (4, 7), (0, 1), (2, 3), (4, 5), (6, 7)]
    # data travels with a box: the depth of each box visited
    assert [d for _, d in seen] == [0, 1, 1, 2, 2, 2, 2]
    assert work == 7
    assert sorted(b["x"] for _, _, b, _ in left) == [(k, k) for k in range(8)]


def test_the_budget_leaves_the_boxes_never_visited():
    seen = []
    work, left = finish(search({"x": (0, 7)}, -8, _halving(seen), budget=3, data=0))
    assert work == 3 and len(seen) == 3
    assert sorted(b["x"] for _, _, b, _ in left) == [(0, 1), (2, 3), (4, 5), (6, 7)]
    assert all(d == 2 for _, _, _, d in left)


def test_a_visit_counts_its_own_work():
    # cost 3 per box, budget 5: the second box starts at work 3 < 5, the third at 6 does not
    seen = []
    work, _ = finish(search({"x": (0, 7)}, -8, _halving(seen, cost=3), budget=5, data=0))
    assert len(seen) == 2 and work == 6


def test_children_none_stops_after_counting_the_work():
    def visit(key, box, data):
        return (2, None) if box["x"] == (0, 3) else (1, [(-volume(h), h, None)
                                                         for h in halve(box, "x")])
    work, left = finish(search({"x": (0, 7)}, -8, visit, budget=100))
    assert work == 3
    assert [b["x"] for _, _, b, _ in left] == [(4, 7)]


def test_yields_every_n_units_of_work():
    steps = search({"x": (0, 7)}, -8, _halving([]), budget=15, data=0, every=4)
    yields = 0
    while True:
        try:
            next(steps)
            yields += 1
        except StopIteration as end:
            work, left = end.value
            break
    # 15 boxes visited; a yield before the box after work 4, 8 and 12
    assert (work, yields, left) == (15, 3, [])
