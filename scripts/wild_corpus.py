#!/usr/bin/python3
"""Models from the wild, made from the ones we have: CGAL's data-set meshes and the shared
benchmark meshes with damage applied, each unwrapped by uv_unwrap with its defaults.

Damage (deterministic, seeded by the mesh's name):
  holes     faces in 3 random balls removed
  dup       2% of the faces repeated (half of them reversed, some with rotated corners)
  fins      edges of 3 and 4 faces: triangles hung on 10 interior edges (one or two per edge)
  flip      a patch of 10% of the faces in reversed orientation
  parts     cut into separate parts along a plane (each part gets its own vertices)
  polygons  adjacent triangles merged into quads, and the fans of a few vertices into n-gons
  refine    midpoint subdivision (1 -> 4 triangles) up to 100k faces at least, for the meshes
            that it takes to 100k-160k faces
  none      the mesh as it is

Prints one line per run as it goes, then a table sorted by time with the slowest ten, the
independent measures of tools/uv_metrics.py (E_d, flips, crossings) beside uv_unwrap's own.
Needs python3 with numpy (Debian: /usr/bin/python3 with python3-numpy).

  /usr/bin/python3 scripts/wild_corpus.py [--meshes DIR...] [--damage holes,dup,...]
      [--min-faces N] [--max-faces N] [--timeout S] [--work DIR] [--uv-unwrap EXE] [--metrics uv_metrics.py]
      [--filter SUBSTRING] [--skip NAME,...] [--after NAME] [--every K] [--keep]

Defaults: build/data/meshes (CGAL's data set, extracted by the build) and ../shared/meshes,
build/bin/uv_unwrap, ../shared/tools/uv_metrics.py, build/wild_corpus, all damages, meshes
up to 130k faces, 600 s per run.
"""
import argparse, hashlib, json, os, random, subprocess, sys, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def read_mesh(path):
    """Points (n x 3) and polygons (lists of 0-based indices) of an OFF or OBJ file; None if unread."""
    try:
        with open(path, 'rb') as f:
            text = f.read().decode('latin-1')
    except OSError:
        return None
    if path.lower().endswith('.obj'):
        pts, faces = [], []
        for line in text.splitlines():
            t = line.split()
            if not t:
                continue
            if t[0] == 'v' and len(t) >= 4:
                pts.append([float(x) for x in t[1:4]])
            elif t[0] == 'f' and len(t) >= 4:
                idx = []
                for c in t[1:]:
                    i = int(c.split('/')[0])
                    idx.append(i - 1 if i > 0 else len(pts) + i)
                faces.append(idx)
        return np.array(pts, dtype=float), faces
    if path.lower().endswith('.off'):
        tokens = []
        for line in text.splitlines():
            line = line.split('#')[0].strip()
            if line:
                tokens.append(line.split())
        if not tokens or not tokens[0][0].endswith('OFF'):
            return None
        head = tokens[0][1:] if len(tokens[0]) > 1 else None
        rows = tokens[1:] if head is None else [head] + tokens[1:]
        if tokens[0][0] != 'OFF':
            return None  # colored / textured variants: left out
        try:
            nv, nf = int(rows[0][0]), int(rows[0][1])
            pts = np.array([[float(x) for x in rows[1 + i][:3]] for i in range(nv)], dtype=float)
            faces = []
            for i in range(nf):
                r = rows[1 + nv + i]
                k = int(r[0])
                faces.append([int(x) for x in r[1:1 + k]])
        except (ValueError, IndexError):
            return None
        return pts, faces
    return None


def write_obj(path, pts, faces):
    with open(path, 'w') as f:
        f.write(''.join('v %.9g %.9g %.9g\n' % tuple(p) for p in pts))
        f.write(''.join('f ' + ' '.join(str(i + 1) for i in fc) + '\n' for fc in faces))


def triangles(faces):
    out = []
    for fc in faces:
        for k in range(1, len(fc) - 1):
            out.append([fc[0], fc[k], fc[k + 1]])
    return out


def edge_faces(faces):
    m = {}
    for fi, fc in enumerate(faces):
        for k in range(len(fc)):
            a, b = fc[k], fc[(k + 1) % len(fc)]
            m.setdefault((min(a, b), max(a, b)), []).append(fi)
    return m


def diagonal(pts):
    return float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0))) or 1.


def damage_holes(pts, faces, rng):
    cen = np.array([pts[f].mean(axis=0) for f in faces])
    r = 0.06 * diagonal(pts)
    drop = np.zeros(len(faces), bool)
    for _ in range(3):
        c = cen[rng.randrange(len(faces))]
        drop |= np.linalg.norm(cen - c, axis=1) < r
    return pts, [f for f, d in zip(faces, drop) if not d]


def damage_dup(pts, faces, rng):
    extra = []
    for _ in range(max(1, len(faces) // 50)):
        f = list(faces[rng.randrange(len(faces))])
        if rng.random() < 0.5:
            f = f[::-1]
        k = rng.randrange(len(f))
        extra.append(f[k:] + f[:k])
    return pts, faces + extra


def damage_fins(pts, faces, rng):
    edges = edge_faces(faces)
    ef = [e for e, fs in edges.items() if len(fs) == 2] or list(edges)  # interior edges, else any
    pts = list(map(list, pts))
    out = list(faces)
    d = 0.02 * diagonal(np.array(pts))
    for _ in range(10):
        a, b = ef[rng.randrange(len(ef))]
        for _ in range(rng.choice((1, 2))):  # 3 or 4 faces on the edge
            m = [(pts[a][k] + pts[b][k]) / 2 + rng.uniform(-d, d) for k in range(3)]
            pts.append(m)
            out.append([a, b, len(pts) - 1])
    return np.array(pts), out


def damage_flip(pts, faces, rng):
    ef = edge_faces(faces)
    nbr = [[] for _ in faces]
    for fs in ef.values():
        for i in fs:
            nbr[i].extend(j for j in fs if j != i)
    seed = rng.randrange(len(faces))
    seen, queue = {seed}, [seed]
    while queue and len(seen) < max(1, len(faces) // 10):
        f = queue.pop(0)
        for g in nbr[f]:
            if g not in seen:
                seen.add(g)
                queue.append(g)
    return pts, [f[::-1] if i in seen else f for i, f in enumerate(faces)]


def damage_parts(pts, faces, rng):
    axis = rng.randrange(3)
    cen = np.array([pts[f].mean(axis=0) for f in faces])
    cut = np.median(cen[:, axis])
    pts2 = list(map(list, pts))
    copy = {}
    out = []
    for f, c in zip(faces, cen):
        if c[axis] > cut:
            g = []
            for i in f:
                if i not in copy:
                    copy[i] = len(pts2)
                    pts2.append(list(pts[i]))
                g.append(copy[i])
            out.append(g)
        else:
            out.append(list(f))
    return np.array(pts2), out


def damage_polygons(pts, faces, rng):
    tris = triangles(faces)
    ef = edge_faces(tris)
    used = [False] * len(tris)
    out = []
    # n-gons: the fans of a few interior vertices of valence 5..8 merged (the vertex is left isolated)
    star = {}
    for fi, f in enumerate(tris):
        for v in f:
            star.setdefault(v, []).append(fi)
    order = list(star)
    rng.shuffle(order)
    made = 0
    for v in order:
        if made >= 20:
            break
        fs = star[v]
        if not 5 <= len(fs) <= 8 or any(used[f] for f in fs):
            continue
        nxt = {}
        for f in fs:
            t = tris[f]
            k = t.index(v)
            nxt[t[(k + 1) % 3]] = t[(k + 2) % 3]
        if len(nxt) != len(fs):
            continue
        start = next(iter(nxt))
        ring, c = [start], nxt[start]
        while c != start and c in nxt and len(ring) <= len(fs):
            ring.append(c)
            c = nxt[c]
        if c != start or len(ring) != len(fs):
            continue
        for f in fs:
            used[f] = True
        out.append(ring)
        made += 1
    # quads: pairs of triangles across an edge
    for (a, b), fs in ef.items():
        if len(fs) != 2 or used[fs[0]] or used[fs[1]] or rng.random() < 0.3:
            continue
        t0, t1 = tris[fs[0]], tris[fs[1]]
        c = [v for v in t0 if v not in (a, b)]
        d = [v for v in t1 if v not in (a, b)]
        if len(c) != 1 or len(d) != 1:
            continue
        k = t0.index(c[0])
        p, q = t0[(k + 1) % 3], t0[(k + 2) % 3]  # t0 = c, p, q; t1 holds q, p
        out.append([c[0], p, d[0], q])
        used[fs[0]] = used[fs[1]] = True
    out += [t for t, u in zip(tris, used) if not u]
    return pts, out


def damage_refine(pts, faces, rng):
    tris = triangles(faces)
    pts = [tuple(p) for p in pts]
    while len(tris) < 100000:
        mid = {}
        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                mid[key] = len(pts)
                pts.append(tuple((pts[a][k] + pts[b][k]) / 2 for k in range(3)))
            return mid[key]
        new = []
        for a, b, c in tris:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            new += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        tris = new
    return np.array(pts), tris


DAMAGES = {'none': None, 'holes': damage_holes, 'dup': damage_dup, 'fins': damage_fins, 'flip': damage_flip,
           'parts': damage_parts, 'polygons': damage_polygons, 'refine': damage_refine}


def run(args, path, name):
    out = os.path.join(args.work, name + '_uv.obj')
    stats = os.path.join(args.work, name + '.json')
    for f in (out, stats):
        if os.path.exists(f):
            os.remove(f)
    start = time.time()
    cpu0 = os.times()
    try:
        p = subprocess.run([args.uv_unwrap, path, '-q', '-o', out, '--stats', stats], capture_output=True,
                           timeout=args.timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        rc = 'timeout'
    cpu1 = os.times()
    row = {'name': name, 'rc': rc, 'wall': time.time() - start,
           'cpu': (cpu1.children_user - cpu0.children_user) + (cpu1.children_system - cpu0.children_system)}
    try:
        s = json.load(open(stats))
        row.update(status=s['status'], faces=s['faces'], E_d=s['distortion'], flips=s['flipped_faces'],
                   crossings=s['border_crossings'], unit=s['uv_in_unit_square'], newton=s['newton_iterations'],
                   charts=s['charts'], time=s['time_seconds'], error=s['error'])
    except (OSError, ValueError, KeyError):
        row.update(status='no statistics', faces=None)
    if row.get('status') == 'ok' and args.metrics and os.path.exists(out):
        try:
            m = subprocess.run([sys.executable, args.metrics, out], capture_output=True, text=True, timeout=600)
            last = m.stdout.strip().splitlines()[-1] if m.stdout.strip() else m.stderr.strip()[-200:]
            row['metrics'] = last.split(' ', 1)[1] if last.startswith(out) else last
        except subprocess.TimeoutExpired:
            row['metrics'] = 'timeout'
    return row


def fmt(x, spec):
    return format(x, spec) if isinstance(x, (int, float)) and not isinstance(x, bool) else str(x)


def line(r):
    return '%-44s %7s %8s %8s %6s %8s %5s %5s %5s %6s  %s' % (
        r['name'][:44], fmt(r.get('faces'), 'd'), fmt(r.get('wall'), '.1f'), fmt(r.get('cpu'), '.1f'),
        fmt(r.get('newton'), 'd'), fmt(r.get('E_d'), '.3f'), fmt(r.get('flips'), 'd'), fmt(r.get('crossings'), 'd'),
        'yes' if r.get('unit') else 'no', str(r.get('status'))[:6] if r.get('status') != 'ok' else 'ok',
        r.get('metrics', r.get('error') or ''))


HEADER = '%-44s %7s %8s %8s %6s %8s %5s %5s %5s %6s  %s' % (
    'mesh/damage', 'faces', 'wall s', 'cpu s', 'newton', 'E_d', 'flips', 'cross', '[0,1]', 'status',
    'uv_metrics.py (independent)')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--meshes', nargs='*', default=[os.path.join(ROOT, 'build', 'data', 'meshes'),
                                                    os.path.join(ROOT, '..', 'shared', 'meshes')])
    ap.add_argument('--damage', default=','.join(DAMAGES))
    ap.add_argument('--max-faces', type=int, default=130000)
    ap.add_argument('--min-faces', type=int, default=0,
                    help='only the meshes of at least N faces before damage (the refined ones count as 100k)')
    ap.add_argument('--timeout', type=float, default=600)
    ap.add_argument('--work', default=os.path.join(ROOT, 'build', 'wild_corpus'))
    ap.add_argument('--uv-unwrap', default=os.path.join(ROOT, 'build', 'bin', 'uv_unwrap'))
    ap.add_argument('--metrics', default=os.path.join(ROOT, '..', 'shared', 'tools', 'uv_metrics.py'))
    ap.add_argument('--filter', default='')
    ap.add_argument('--skip', default='', help='comma-separated mesh names left out')
    ap.add_argument('--after', default='', help='only the meshes whose name sorts after this (to resume a run)')
    ap.add_argument('--every', type=int, default=1, help='every K-th mesh only (a quicker sample)')
    ap.add_argument('--json', default='', help='also write the rows to this file')
    ap.add_argument('--keep', action='store_true', help='keep the damaged meshes in the work directory')
    args = ap.parse_args()
    if args.metrics and not os.path.exists(args.metrics):
        args.metrics = ''
    os.makedirs(args.work, exist_ok=True)
    files = []
    for d in args.meshes:
        for dirpath, _, names in os.walk(d):
            files += [os.path.join(dirpath, n) for n in sorted(names) if n.lower().endswith(('.off', '.obj'))]
    skip = set(n for n in args.skip.split(',') if n)
    files = sorted(f for f in files if args.filter in os.path.basename(f)
                   and os.path.splitext(os.path.basename(f))[0] not in skip)[::args.every]
    files = [f for f in files if os.path.splitext(os.path.basename(f))[0].lower() > args.after.lower()]
    damages = [d for d in args.damage.split(',') if d]
    rows = []
    print(HEADER, flush=True)
    for path in files:
        mesh = read_mesh(path)
        if mesh is None or not len(mesh[1]):
            continue
        pts, faces = mesh
        if any(len(f) < 3 or min(f) < 0 or max(f) >= len(pts) for f in faces):
            continue
        stem = os.path.splitext(os.path.basename(path))[0]
        for d in damages:
            if d == 'refine' and not any(100000 <= len(faces) * 4 ** k <= 160000 for k in (1, 2, 3)):
                continue
            if d != 'refine' and len(faces) > args.max_faces:
                continue
            if (100000 if d == 'refine' else len(faces)) < args.min_faces:
                continue
            rng = random.Random(int(hashlib.md5((stem + d).encode()).hexdigest()[:8], 16))
            try:
                p, f = (pts, faces) if DAMAGES[d] is None else DAMAGES[d](pts, [list(x) for x in faces], rng)
            except (ValueError, IndexError) as e:  # a damage that does not apply to this mesh
                print('%s.%s: damage not applied (%s)' % (stem, d, e), flush=True)
                continue
            if not f:  # the damage left no face (holes in a tiny mesh): nothing to unwrap
                continue
            name = stem + '.' + d
            mesh_file = os.path.join(args.work, name + '.obj')
            write_obj(mesh_file, p, f)
            r = run(args, mesh_file, name)
            rows.append(r)
            print(line(r), flush=True)
            if args.json:  # after each run, so that an interrupted run keeps its rows
                json.dump(rows, open(args.json, 'w'), indent=1)
            if not args.keep:
                os.remove(mesh_file)
    ok = [r for r in rows if r.get('status') == 'ok']
    bad = [r for r in rows if r.get('status') != 'ok' or r.get('flips') or r.get('crossings') or not r.get('unit')]
    print('\n%d runs: %d ok, %d not a valid atlas or failed; E_d above 4.6: %d; above 30 s: %d (%d of up to 130k faces)' % (
        len(rows), len(ok), len(bad), sum(1 for r in ok if (r.get('E_d') or 0) > 4.6),
        sum(1 for r in rows if r['wall'] > 30),
        sum(1 for r in rows if r['wall'] > 30 and (r.get('faces') or 0) <= 130000)))
    print('\nslowest ten (wall time; other engineers\' compiles share the machine: see cpu s and newton):')
    print(HEADER)
    for r in sorted(rows, key=lambda r: -r['wall'])[:10]:
        print(line(r))
    if bad:
        print('\nfailed or invalid:')
        print(HEADER)
        for r in bad:
            print(line(r))
    high = [r for r in ok if (r.get('E_d') or 0) > 4.6]
    if high:
        print('\nE_d above 4.6:')
        print(HEADER)
        for r in sorted(high, key=lambda r: -r['E_d']):
            print(line(r))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
