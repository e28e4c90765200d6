"""Where relay drones stand: a tree over the BS and the searchers, and who flies where.

The placement is the MST heuristic for Steiner trees with bounded edge length (Lin and Xue,
1999; ratio 4 in the Euclidean plane, Mandoiu and Zelikovsky, 2000; docs/model.md, Relays):
Prim's minimum spanning tree over the terminals (the root, by convention the BS, and the
searchers), then ``ceil(L / r_c) - 1`` points evenly spaced on each tree edge of length ``L``,
so that every link of the tree is at most ``r_c``. An edge counts as within ``r_c`` when
``L <= r_c + TOL``: an edge of exactly ``r_c`` takes no relay, one of ``2 r_c`` takes one.
By default (:func:`tree`) branch points, each a relay, are added where a 3-star over a node
and two of its tree neighbours needs fewer relays than the two edges it replaces (the 3-star
idea of Chen, Du, Hu, Lin, Wang and Xue, 2000), which never raises the count.

With fewer relays than the tree needs, a priority (:class:`sarlink.engine.codes.Priority`)
chooses which edges get theirs; with more, the spare relays hold where they are. The relays
then go to the points by a bottleneck assignment: the longest flight as short as it can be,
and among such assignments the least total flight. A point outside the area or in a hole is
moved to the nearest point inside.

Every function takes and returns arrays and scalars only, and nothing is random: the same
positions give the same plan, so the kernel can re-plan at every decision step.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.area import contains
from sarlink.engine.codes import Priority

TOL = 1e-9
"""Metres by which a link may exceed ``r_c`` and still count as within it, everywhere in this
module: a tree edge of length ``k r_c`` (up to rounding) needs ``k - 1`` relays, not ``k``."""
NUDGE = 1e-3
"""Metres past the boundary a point moved into the area is put, so that it is inside and not
on the boundary (halved while that is not yet inside, in a sliver narrower than this)."""

NEAREST = int(Priority.NEAREST)
MOST = int(Priority.MOST)
BOTTLENECK = int(Priority.BOTTLENECK)


@njit(cache=True, inline="always", error_model="numpy")
def dist(ax: float, ay: float, bx: float, by: float) -> float:
    """The distance from a to b as ``sqrt(dx² + dy²)``, which plain Python reproduces bit for
    bit (Numba's ``math.hypot`` and CPython's differ in the last bit)."""
    dx = ax - bx
    dy = ay - by
    return math.sqrt(dx * dx + dy * dy)


@njit(cache=True, error_model="numpy")
def spanning_tree(x: np.ndarray, y: np.ndarray, root: int) -> tuple[np.ndarray, np.ndarray]:
    """Prim's minimum spanning tree over the points ``(x, y)`` grown from ``root``, O(n²).

    Returns ``parent`` (``-1`` at the root) and ``order``, the nodes as they joined the tree
    (each after its parent). Ties go to the lower index, so the tree is a function of the
    points alone.
    """
    n = x.shape[0]
    parent = np.full(n, -1, dtype=np.int64)
    order = np.empty(n, dtype=np.int64)
    best = np.full(n, np.inf)
    done = np.zeros(n, dtype=np.bool_)
    best[root] = 0.0
    for k in range(n):
        u = -1
        for v in range(n):
            if not done[v] and (u < 0 or best[v] < best[u]):
                u = v
        done[u] = True
        order[k] = u
        for v in range(n):
            if not done[v]:
                d = dist(x[v], y[v], x[u], y[u])
                if d < best[v]:
                    best[v] = d
                    parent[v] = u
    return parent, order


@njit(cache=True, inline="always", error_model="numpy")
def chain(length: float, rc: float) -> int:
    """The relays a straight link of ``length`` m needs so that each hop is at most ``r_c``
    (within :data:`TOL`)."""
    return max(0, math.ceil((length - TOL) / rc) - 1)


@njit(cache=True, error_model="numpy")
def edge_needs(x: np.ndarray, y: np.ndarray, parent: np.ndarray,
               rc: float) -> tuple[np.ndarray, np.ndarray]:
    """Each tree edge's length and the relays it needs, indexed by the edge's child node (0
    at the root)."""
    n = x.shape[0]
    length = np.zeros(n)
    need = np.zeros(n, dtype=np.int64)
    for v in range(n):
        p = parent[v]
        if p >= 0:
            length[v] = dist(x[v], y[v], x[p], y[p])
            need[v] = chain(length[v], rc)
    return length, need


@njit(cache=True, error_model="numpy")
def _centres(ax: float, ay: float, bx: float, by: float, cx: float,
             cy: float) -> tuple[float, float, float, float]:
    """Two candidate branch points for three nodes: the Fermat point (least total leg length;
    Weiszfeld's iteration, a fixed number of steps) and the centre of the smallest circle
    round them (the shortest longest leg). The caller passes the three in a fixed order of
    their coordinates, so that the result does not depend on how the nodes are numbered."""
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0.0:  # collinear: no branch
        return ax, ay, ax, ay
    fx, fy = (ax + bx + cx) / 3.0, (ay + by + cy) / 3.0
    for _ in range(64):
        da, db, dc = dist(fx, fy, ax, ay), dist(fx, fy, bx, by), dist(fx, fy, cx, cy)
        if da < 1e-9 or db < 1e-9 or dc < 1e-9:
            break
        w = 1.0 / da + 1.0 / db + 1.0 / dc
        fx = (ax / da + bx / db + cx / dc) / w
        fy = (ay / da + by / db + cy / dc) / w
    ab, bc, ca = dist(ax, ay, bx, by), dist(bx, by, cx, cy), dist(cx, cy, ax, ay)
    if ab * ab >= bc * bc + ca * ca:  # right or obtuse: the longest side's midpoint
        return fx, fy, (ax + bx) / 2.0, (ay + by) / 2.0
    if bc * bc >= ab * ab + ca * ca:
        return fx, fy, (bx + cx) / 2.0, (by + cy) / 2.0
    if ca * ca >= ab * ab + bc * bc:
        return fx, fy, (cx + ax) / 2.0, (cy + ay) / 2.0
    d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    a2, b2, c2 = ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy
    return (fx, fy, (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d,
            (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d)


@njit(cache=True, error_model="numpy")
def _circles(ax: float, ay: float, ra: float, bx: float, by: float, rb: float,
             cx: np.ndarray, cy: np.ndarray, k: int) -> int:
    """The points where the circles of radius ``ra`` round a and ``rb`` round b cross, put
    at ``cx[k:]``, ``cy[k:]``; returns ``k`` plus their number (none, one or two)."""
    d = dist(ax, ay, bx, by)
    if d == 0.0 or d > ra + rb or d < abs(ra - rb):
        return k
    along = (ra * ra - rb * rb + d * d) / (2.0 * d)
    h = math.sqrt(max(ra * ra - along * along, 0.0))
    ux, uy = (bx - ax) / d, (by - ay) / d
    for sign in (1.0, -1.0):
        cx[k] = ax + along * ux - sign * h * uy
        cy[k] = ay + along * uy + sign * h * ux
        k += 1
    return k


SLACK = 1e-6
"""Metres inside a circle of a whole number of ranges that a candidate branch point is put,
so that rounding does not push its leg past the range."""


@njit(cache=True, error_model="numpy")
def _candidates(x: np.ndarray, y: np.ndarray, a: int, b: int, c: int, rc: float,
                cx: np.ndarray, cy: np.ndarray) -> int:
    """Candidate branch points for the nodes a, b, c (given in a fixed order of their
    coordinates, so that the candidates do not depend on how the nodes are numbered): the two
    :func:`_centres`, and where circles of a whole number of ranges (less :data:`SLACK`) round
    two of them cross, for the chain counts the Fermat point's legs have, one more, and up to
    two fewer: a point with the fewest relays on its three legs lies, if not on a node, at
    such a crossing. Returns how many are in ``cx``, ``cy``."""
    f1, f2, g1, g2 = _centres(x[a], y[a], x[b], y[b], x[c], y[c])
    cx[0], cy[0], cx[1], cy[1] = f1, f2, g1, g2
    k = 2
    three = (a, b, c)
    for i in range(3):
        for j in range(i + 1, 3):
            p, q = three[i], three[j]
            kp = chain(dist(f1, f2, x[p], y[p]), rc)
            kq = chain(dist(f1, f2, x[q], y[q]), rc)
            for hp in range(max(kp - 2, 0), kp + 2):
                for hq in range(max(kq - 2, 0), kq + 2):
                    k = _circles(x[p], y[p], (hp + 1) * rc - SLACK, x[q], y[q],
                                 (hq + 1) * rc - SLACK, cx, cy, k)
    return k


@njit(cache=True, inline="always", error_model="numpy")
def _before(ax: float, ay: float, bx: float, by: float) -> bool:
    return ax < bx or (ax == bx and ay < by)


@njit(cache=True, error_model="numpy")
def _pruned(x: np.ndarray, y: np.ndarray, m: int, terminals: int,
            root: int) -> tuple[int, np.ndarray, np.ndarray]:
    """Prim's tree over the first ``m`` nodes, after dropping every branch point (node
    ``>= terminals``) of degree two or less in it, one at a time (which never costs a relay:
    ``chain(|ab|) <= chain(|as|) + chain(|sb|) + 1``). Returns the nodes left and the tree."""
    while True:
        parent, order = spanning_tree(x[:m], y[:m], root)
        degree = np.zeros(m, dtype=np.int64)
        for v in range(m):
            if parent[v] >= 0:
                degree[v] += 1
                degree[parent[v]] += 1
        drop = -1
        for v in range(terminals, m):
            if degree[v] <= 2:
                drop = v
                break
        if drop < 0:
            return m, parent, order
        for v in range(drop, m - 1):
            x[v], y[v] = x[v + 1], y[v + 1]
        m -= 1


@njit(cache=True, error_model="numpy")
def tree(tx: np.ndarray, ty: np.ndarray, root: int, rc: float, branch: bool
         ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The tree the relays hold: the terminals' minimum spanning tree, and with ``branch``
    branch points added where a 3-star saves relays (docs/model.md, Relays).

    The 3-star step: for every node v and two of its tree neighbours u, w, a branch point s
    (:func:`_centres`) joined to v, u and w replaces the edges vu and vw when
    ``1 + chain(|sv|) + chain(|su|) + chain(|sw|)`` is less than their relays; the star that
    saves the most (then shortens the tree most) is taken, the tree is re-spanned over the
    terminals and branch points (the minimum spanning tree has the fewest relays for its
    nodes, ``chain`` being monotone), branch points of degree two or less are dropped, and
    the step repeats until no star saves a relay. Each step saves at least one, so the count
    is never above the spanning tree's.

    Returns the nodes' coordinates (the terminals first, then the branch points), each node's
    parent (``-1`` at the root) and the order they join, and each edge's length and relays
    by child node, a branch point's own relay counted on the edge to its parent.
    """
    n = tx.shape[0]
    x = np.empty(2 * n)
    y = np.empty(2 * n)
    x[:n] = tx
    y[:n] = ty
    m = n
    qx = np.empty(2 + 3 * 4 * 4 * 2)  # room for every candidate of :func:`_candidates`
    qy = np.empty_like(qx)
    parent, order = spanning_tree(tx, ty, root)
    while branch and n >= 3:
        length, need = edge_needs(x[:m], y[:m], parent, rc)
        near = np.full((m, m), -1, dtype=np.int64)  # each node's tree neighbours
        deg = np.zeros(m, dtype=np.int64)
        for v in range(m):
            p = parent[v]
            if p >= 0:
                near[v, deg[v]] = p
                deg[v] += 1
                near[p, deg[p]] = v
                deg[p] += 1
        gain, shorter, sx, sy = 0, 0.0, 0.0, 0.0
        for v in range(m):
            for i in range(deg[v]):
                for j in range(i + 1, deg[v]):
                    u, w = near[v, i], near[v, j]
                    eu = u if parent[u] == v else v  # the edges' child nodes
                    ew = w if parent[w] == v else v
                    old = need[eu] + need[ew]
                    if old < 2:  # a star costs its centre: nothing to save
                        continue
                    a, b, c = v, u, w  # in the order of their coordinates
                    if _before(x[b], y[b], x[a], y[a]):
                        a, b = b, a
                    if _before(x[c], y[c], x[b], y[b]):
                        b, c = c, b
                        if _before(x[b], y[b], x[a], y[a]):
                            a, b = b, a
                    for q in range(_candidates(x, y, a, b, c, rc, qx, qy)):
                        cx, cy = qx[q], qy[q]
                        la, lb, lc = (dist(cx, cy, x[a], y[a]), dist(cx, cy, x[b], y[b]),
                                      dist(cx, cy, x[c], y[c]))
                        saves = old - 1 - chain(la, rc) - chain(lb, rc) - chain(lc, rc)
                        cut = length[eu] + length[ew] - la - lb - lc
                        if saves > gain or (saves == gain and saves > 0 and cut > shorter):
                            gain, shorter, sx, sy = saves, cut, cx, cy
        if gain <= 0:
            break
        x[m], y[m] = sx, sy
        m, parent, order = _pruned(x, y, m + 1, n, root)
    x = x[:m].copy()
    y = y[:m].copy()
    length, need = edge_needs(x, y, parent, rc)
    for v in range(n, m):
        need[v] += 1
    return x, y, parent, order, length, need


@njit(cache=True, error_model="numpy")
def _nearest_first(x: np.ndarray, y: np.ndarray, root: int, parent: np.ndarray,
                   order: np.ndarray, need: np.ndarray, relays: int) -> np.ndarray:
    """The relays per edge under "nearest first": the searchers in order of the relays their
    path from the root needs (ties: distance to the root, then index), each taking its path's
    still missing relays if they are left; one that does not fit is skipped."""
    n = x.shape[0]
    cost = np.zeros(n, dtype=np.int64)
    for k in range(1, n):
        v = order[k]
        cost[v] = cost[parent[v]] + need[v]
    away = np.empty(n)
    for v in range(n):
        away[v] = dist(x[v], y[v], x[root], y[root])
    queue = np.empty(n - 1, dtype=np.int64)  # insertion sort by (cost, dist, index)
    m = 0
    for v in range(n):
        if v == root:
            continue
        j = m
        while j > 0 and (cost[queue[j - 1]] > cost[v] or (
                cost[queue[j - 1]] == cost[v] and away[queue[j - 1]] > away[v])):
            queue[j] = queue[j - 1]
            j -= 1
        queue[j] = v
        m += 1
    built = np.zeros(n, dtype=np.bool_)
    left = relays
    for k in range(m):
        missing = 0
        v = queue[k]
        while v != root and not built[v]:
            missing += need[v]
            v = parent[v]
        if missing <= left:
            left -= missing
            v = queue[k]
            while v != root and not built[v]:
                built[v] = True
                v = parent[v]
    alloc = np.zeros(n, dtype=np.int64)
    for v in range(n):
        if built[v]:
            alloc[v] = need[v]
    return alloc


@njit(cache=True, error_model="numpy")
def _most_connected(root: int, parent: np.ndarray, order: np.ndarray, need: np.ndarray,
                    relays: int) -> np.ndarray:
    """The relays per edge under "most connected": the subtree around the root that holds
    the most searchers for at most ``relays`` relays, and of those the one that needs fewest
    (a knapsack over the tree, O(n K²)). Equal choices go to leaving a child out, then to the
    fewest relays on it."""
    n = parent.shape[0]
    k1 = relays + 1
    best = np.zeros((n, k1), dtype=np.int64)  # most terminals below and at v, v connected
    after = np.zeros((n, k1), dtype=np.int64)  # at parent[c], once its children up to c are in
    before = np.full(n, -1, dtype=np.int64)  # the sibling merged just before c (-1: none)
    last = np.full(n, -1, dtype=np.int64)  # the child of v merged last
    for k in range(1, n):
        c = order[k]
        before[c] = last[parent[c]]
        last[parent[c]] = c
    for k in range(n - 1, -1, -1):
        v = order[k]
        own = 0 if v == root else 1
        c = last[v]
        kids = np.empty(n, dtype=np.int64)  # v's children, last merged first
        m = 0
        while c >= 0:
            kids[m] = c
            m += 1
            c = before[c]
        cur = np.full(k1, own, dtype=np.int64)
        for i in range(m - 1, -1, -1):
            c = kids[i]
            new = cur.copy()
            for b in range(need[c], k1):
                for j in range(need[c], b + 1):
                    got = cur[b - j] + best[c, j - need[c]]
                    if got > new[b]:
                        new[b] = got
            after[c] = new
            cur = new
        best[v] = cur
    spend = relays
    while spend > 0 and best[root, spend - 1] == best[root, relays]:
        spend -= 1
    alloc = np.zeros(n, dtype=np.int64)
    budget = np.zeros(n, dtype=np.int64)
    taken = np.zeros(n, dtype=np.bool_)
    taken[root] = True
    budget[root] = spend
    for k in range(n):  # parents before children: share each taken node's budget out
        v = order[k]
        if not taken[v]:
            continue
        b = budget[v]
        c = last[v]
        while c >= 0:
            prev = before[c]
            start = after[prev] if prev >= 0 else np.full(k1, 0 if v == root else 1,
                                                          dtype=np.int64)
            if start[b] != after[c, b]:  # c is in: the fewest relays that give the value
                for j in range(need[c], b + 1):
                    if start[b - j] + best[c, j - need[c]] == after[c, b]:
                        taken[c] = True
                        alloc[c] = need[c]
                        budget[c] = j - need[c]
                        b -= j
                        break
            c = prev
    return alloc


@njit(cache=True, error_model="numpy")
def _k_bottleneck(root: int, length: np.ndarray, need: np.ndarray,
                  relays: int) -> np.ndarray:
    """The relays per edge under "k-bottleneck": each relay in turn to the edge whose hops are
    longest (ties: the lower index), which makes the tree's longest hop as short as ``relays``
    relays can on the tree's edges."""
    n = length.shape[0]
    alloc = np.zeros(n, dtype=np.int64)
    for _ in range(relays):
        u, hop = -1, -1.0
        for v in range(n):
            if v != root and length[v] / (alloc[v] + 1) > hop:
                u, hop = v, length[v] / (alloc[v] + 1)
        alloc[u] += 1
    return alloc


@njit(cache=True, error_model="numpy")
def allocate(x: np.ndarray, y: np.ndarray, root: int, parent: np.ndarray, order: np.ndarray,
             length: np.ndarray, need: np.ndarray, relays: int, priority: int) -> np.ndarray:
    """The relays on each tree edge (by child node) for ``relays`` relays: every edge's need
    when they suffice, else the ``priority``'s choice (:class:`sarlink.engine.codes.Priority`)."""
    if relays >= need.sum():
        return need.copy()
    if priority == MOST:
        return _most_connected(root, parent, order, need, relays)
    if priority == BOTTLENECK:
        return _k_bottleneck(root, length, need, relays)
    return _nearest_first(x, y, root, parent, order, need, relays)


@njit(cache=True, error_model="numpy")
def linked(root: int, parent: np.ndarray, order: np.ndarray, need: np.ndarray,
           alloc: np.ndarray) -> np.ndarray:
    """Which terminals the allocation links to the root: those whose every edge on the way
    has the relays it needs."""
    n = parent.shape[0]
    out = np.zeros(n, dtype=np.bool_)
    out[root] = True
    for k in range(1, n):
        v = order[k]
        out[v] = out[parent[v]] and alloc[v] >= need[v]
    return out


@njit(cache=True, error_model="numpy")
def into_area(x: float, y: float, size: float, edges: np.ndarray) -> tuple[float, float]:
    """``(x, y)`` if it is in the area, else the nearest point of the area: clamped into the
    square ``[0, size]²`` when there are no ``edges``, else the nearest point of the polygon's
    boundary (outline or hole) moved :data:`NUDGE` m on into the area (that point itself if
    no step down to a nanometre lands inside)."""
    if edges.shape[0] == 0:
        return min(max(x, 0.0), size), min(max(y, 0.0), size)
    if contains(x, y, edges):
        return x, y
    near, qx, qy, nx, ny = np.inf, x, y, 0.0, 0.0
    for e in range(edges.shape[0]):
        x1, y1, x2, y2 = edges[e, 0], edges[e, 1], edges[e, 2], edges[e, 3]
        ex, ey = x2 - x1, y2 - y1
        l2 = ex * ex + ey * ey
        t = 0.0 if l2 == 0.0 else min(1.0, max(0.0, ((x - x1) * ex + (y - y1) * ey) / l2))
        px, py = x1 + t * ex, y1 + t * ey
        d = dist(px, py, x, y)
        if d < near and l2 > 0.0:
            near, qx, qy = d, px, py
            nx, ny = -ey / math.sqrt(l2), ex / math.sqrt(l2)
    if near > 0.0:  # on from the point through its nearest boundary point
        nx, ny = (qx - x) / near, (qy - y) / near
    step = NUDGE
    while step > 1e-9:
        for sign in (1.0, -1.0):
            if contains(qx + sign * step * nx, qy + sign * step * ny, edges):
                return qx + sign * step * nx, qy + sign * step * ny
        step *= 0.5
    return qx, qy


@njit(cache=True, error_model="numpy")
def points(x: np.ndarray, y: np.ndarray, parent: np.ndarray, order: np.ndarray,
           alloc: np.ndarray, size: float, edges: np.ndarray,
           terminals: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The relay points: ``alloc[v]`` evenly spaced on the edge from ``parent[v]`` to ``v``,
    from the parent's end, the last of them at ``v`` itself when ``v`` is a branch point
    (a node ``>= terminals``, fully allocated), each moved into the area (:func:`into_area`).
    Returns their coordinates and, for each, the node ``v`` whose edge it lies on (edges in
    the tree's order)."""
    total = alloc.sum()
    px = np.empty(total)
    py = np.empty(total)
    serves = np.empty(total, dtype=np.int64)
    i = 0
    for k in range(order.shape[0]):
        v = order[k]
        a = alloc[v]
        p = parent[v]
        for j in range(1, a + 1):
            f = j / (a + 1) if v < terminals else j / a
            px[i], py[i] = into_area(x[p] + f * (x[v] - x[p]), y[p] + f * (y[v] - y[p]),
                                     size, edges)
            serves[i] = v
            i += 1
    return px, py, serves


@njit(cache=True, error_model="numpy")
def _matches(far: np.ndarray, limit: float, match: np.ndarray, owner: np.ndarray) -> bool:
    """Whether every point (row) gets its own relay (column) at most ``limit`` away: augmenting
    paths by breadth-first search (Kuhn's algorithm). ``match`` (relay of each point) and
    ``owner`` (point of each relay, -1 none) are filled in."""
    p, k = far.shape
    match[:] = -1
    owner[:] = -1
    came = np.empty(k, dtype=np.int64)
    seen = np.empty(k, dtype=np.bool_)
    queue = np.empty(p, dtype=np.int64)
    for s in range(p):
        seen[:] = False
        queue[0] = s
        head, tail, free = 0, 1, -1
        while head < tail and free < 0:
            u = queue[head]
            head += 1
            for j in range(k):
                if not seen[j] and far[u, j] <= limit:
                    seen[j] = True
                    came[j] = u
                    if owner[j] < 0:
                        free = j
                        break
                    queue[tail] = owner[j]
                    tail += 1
        if free < 0:
            return False
        j = free
        while j >= 0:  # flip the path back to s
            u = came[j]
            nxt = match[u]
            match[u] = j
            owner[j] = u
            j = nxt
    return True


@njit(cache=True, error_model="numpy")
def _least_total(cost: np.ndarray) -> np.ndarray:
    """The assignment of each row to its own column with the least total cost (the Hungarian
    method by shortest augmenting paths, O(p² k) for p rows <= k columns)."""
    p, k = cost.shape
    u = np.zeros(p + 1)
    v = np.zeros(k + 1)
    row = np.zeros(k + 1, dtype=np.int64)  # 1-based row on each column, 0 none
    way = np.zeros(k + 1, dtype=np.int64)
    low = np.empty(k + 1)
    used = np.empty(k + 1, dtype=np.bool_)
    for i in range(1, p + 1):
        row[0] = i
        j0 = 0
        low[:] = np.inf
        used[:] = False
        while True:
            used[j0] = True
            i0, delta, j1 = row[j0], np.inf, 0
            for j in range(1, k + 1):
                if not used[j]:
                    c = cost[i0 - 1, j - 1] - u[i0] - v[j]
                    if c < low[j]:
                        low[j] = c
                        way[j] = j0
                    if low[j] < delta:
                        delta = low[j]
                        j1 = j
            for j in range(k + 1):
                if used[j]:
                    u[row[j]] += delta
                    v[j] -= delta
                else:
                    low[j] -= delta
            j0 = j1
            if row[j0] == 0:
                break
        while j0 != 0:
            j1 = way[j0]
            row[j0] = row[j1]
            j0 = j1
    match = np.empty(p, dtype=np.int64)
    for j in range(1, k + 1):
        if row[j] > 0:
            match[row[j] - 1] = j - 1
    return match


@njit(cache=True, error_model="numpy")
def assign(rx: np.ndarray, ry: np.ndarray, px: np.ndarray,
           py: np.ndarray) -> tuple[np.ndarray, float]:
    """The bottleneck assignment of the relays at ``(rx, ry)`` to the points ``(px, py)``
    (no more points than relays): each point its own relay so that the longest flight is as
    short as it can be (a binary search over the distinct distances, each a bipartite
    matching), and among those the least total flight. Returns each relay's point (-1: a
    spare relay) and the longest flight, m (straight, 0 with no points)."""
    k = rx.shape[0]
    p = px.shape[0]
    goal = np.full(k, -1, dtype=np.int64)
    if p == 0:
        return goal, 0.0
    far = np.empty((p, k))
    for i in range(p):
        for j in range(k):
            far[i, j] = dist(px[i], py[i], rx[j], ry[j])
    levels = np.unique(far)
    match = np.empty(p, dtype=np.int64)
    owner = np.empty(k, dtype=np.int64)
    lo, hi = 0, levels.shape[0] - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if _matches(far, levels[mid], match, owner):
            hi = mid
        else:
            lo = mid + 1
    limit = levels[lo]
    dear = (p + 1.0) * (limit + 1.0)  # more than any assignment within the limit
    cost = np.where(far <= limit, far, dear)
    match = _least_total(cost)
    for i in range(p):
        goal[match[i]] = i
    return goal, limit


@njit(cache=True, error_model="numpy")
def plan(tx: np.ndarray, ty: np.ndarray, root: int, rc: float, rx: np.ndarray, ry: np.ndarray,
         priority: int, size: float, edges: np.ndarray, branch: bool = True
         ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int]:
    """One re-plan: where each relay flies to hold the terminals ``(tx, ty)`` (the root, by
    convention the BS at index 0, and the searchers) together at range ``rc``.

    ``(rx, ry)`` are the relays' positions; ``priority`` chooses whom to connect when they
    are too few; ``size`` and ``edges`` are the area (:mod:`sarlink.engine.area`); ``branch``
    adds branch points to the spanning tree (:func:`tree`). When the relays are too few for
    the branched tree, the priority chooses on the spanning tree, whose edges each stand
    alone. Returns each relay's goal (a spare relay's is where it is), the node whose tree
    edge its point lies on (a terminal, or ``n + i`` for the ``i``-th branch point; -1:
    spare), which terminals the plan links to the root, and the relays the tree needs.
    """
    n = tx.shape[0]
    k = rx.shape[0]
    x, y, parent, order, length, need = tree(tx, ty, root, rc, branch)
    fewest = int(need.sum())
    if k < fewest and x.shape[0] > n:
        x, y, parent, order, length, need = tree(tx, ty, root, rc, False)
    alloc = allocate(x, y, root, parent, order, length, need, k, priority)
    px, py, on = points(x, y, parent, order, alloc, size, edges, n)
    goal, _ = assign(rx, ry, px, py)
    gx = rx.copy()
    gy = ry.copy()
    serves = np.full(k, -1, dtype=np.int64)
    for j in range(k):
        if goal[j] >= 0:
            gx[j], gy[j], serves[j] = px[goal[j]], py[goal[j]], on[goal[j]]
    return gx, gy, serves, linked(root, parent, order, need, alloc)[:n], fewest
