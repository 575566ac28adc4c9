// The player of `tamias2d view`: decodes the run embedded in this page (apps/cli/view_html.cpp
// writes it; docs/viewer.md describes it) and draws it on a canvas. It loads nothing: the page
// works from a file, offline. window.tamiasPlayer exposes the decoded states for tests.
// Drawing a world on a canvas: the bodies' shapes, joints, contact points, AABBs, the grid and
// the body under a point. Shared by this player and the live sandbox (apps/wasm/sandbox.js),
// whose page includes this file; the player below runs only in a page that holds a run.
window.TamiasDraw = (function () {
  'use strict';

  const TWO_PI = 2 * Math.PI;
  const FILLS = ['#f2b36b', '#8fc1e3', '#9fd6a4', '#e8a0a0', '#c5a8e0', '#e6d27a'];
  const STROKES = ['#a8692a', '#3f7ca6', '#4f9256', '#a85353', '#7d5aa3', '#9c8a2e'];


  function niceNumber(v) {
    const e = Math.pow(10, Math.floor(Math.log10(v)));
    const m = v / e;
    return +((m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e).toPrecision(3);
  }

  // Per body ({name, type, m, I, lc, geoms}): its shapes, centre of mass in its frame, and the
  // radius of a circle about the centre of mass holding every shape (for culling and picking).
  // `index` picks its colour.
  // Each geometry's kind, from its keys: circle {c, r}, polygon {p}, capsule {cap: ends, r},
  // two-sided segment {seg: ends}, one-sided chain edge {edge: ends}; ends are [x1, y1, x2, y2].
  function kindOf(g) {
    return g.p ? 'polygon' : g.cap ? 'capsule' : g.seg ? 'segment' : g.edge ? 'edge' : 'circle';
  }

  // A segment's, capsule's or chain edge's ends in its body frame: [x1, y1, x2, y2].
  function ends(g) {
    return g.cap || g.seg || g.edge;
  }

  function prepareBody(b, index) {
    let radius = 0;
    const reach = (x, y, r) => { radius = Math.max(radius, Math.hypot(x - b.lc[0], y - b.lc[1]) + r); };
    for (const g of b.geoms) {
      g.kind = kindOf(g);
      if (g.kind === 'circle') reach(g.c[0], g.c[1], g.r);
      else if (g.kind === 'polygon') for (let k = 0; k < g.p.length; k += 2) reach(g.p[k], g.p[k + 1], 0);
      else {
        const e = ends(g), r = g.kind === 'capsule' ? g.r : 0;
        reach(e[0], e[1], r);
        reach(e[2], e[3], r);
      }
    }
    const group = b.type === 'static' ? 'static' : b.type === 'kinematic' ? 'kinematic' : index % FILLS.length;
    return { name: b.name, type: b.type, lc: b.lc, mass: b.m, inertia: b.I, geoms: b.geoms, radius, group };
  }

  // The body frame of a body whose centre of mass is at (x, y), turned by a (rad), with its
  // centre of mass at lc in its frame: origin and rotation.
  function pose(x, y, a, lc) {
    const c = Math.cos(a), s = Math.sin(a);
    return { x, y, c, s, ox: x - (c * lc[0] - s * lc[1]), oy: y - (s * lc[0] + c * lc[1]) };
  }

  // A drawing on `canvas` of the bodies given to setBodies (prepared), at the poses given to
  // each call; view.scale is in device pixels per metre.
  function create(canvas) {
    const ctx = canvas.getContext('2d');
    const view = { cx: 0, cy: 0, scale: 50 };
    let bodies = [], dpr = window.devicePixelRatio || 1;
    const sx = (x) => (x - view.cx) * view.scale + canvas.width / 2;
    const sy = (y) => canvas.height / 2 - (y - view.cy) * view.scale;
    const wx = (px) => (px - canvas.width / 2) / view.scale + view.cx;
    const wy = (py) => (canvas.height / 2 - py) / view.scale + view.cy;

    // Centres the box [x0, y0, x1, y1] (m) in the canvas with a margin of a quarter of it.
    function fitBox(b) {
      const w = b[2] - b[0], h = b[3] - b[1];
      const mx = Math.max(0.25 * w, 0.25 * h, 1), my = Math.max(0.25 * h, 0.25 * w, 1);
      view.cx = (b[0] + b[2]) / 2;
      view.cy = (b[1] + b[3]) / 2;
      view.scale = Math.min(canvas.width / (w + 2 * mx), canvas.height / (h + 2 * my));
    }

    function clear(background) {
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.fillStyle = background;
      ctx.fillRect(0, 0, canvas.width, canvas.height);
    }


    // --- drawing --------------------------------------------------------------------------
    // The shapes with area, outlined (lines: also the segments and chain edges, for a highlight).
    function addBodyPath(b, p, lines) {
      for (const g of bodies[b].geoms) {
        if (g.kind === 'circle') {
          const x = sx(p.ox + p.c * g.c[0] - p.s * g.c[1]), y = sy(p.oy + p.s * g.c[0] + p.c * g.c[1]);
          const r = g.r * view.scale;
          ctx.moveTo(x + r, y);
          ctx.arc(x, y, r, 0, TWO_PI);
        } else if (g.kind === 'capsule') {
          // A rounded rectangle: the half circle round each end, joined by the two sides.
          const e = worldEnds(g, p);
          const x1 = sx(e[0]), y1 = sy(e[1]), x2 = sx(e[2]), y2 = sy(e[3]);
          const a = Math.atan2(y2 - y1, x2 - x1), r = g.r * view.scale;
          ctx.moveTo(x2 + r * Math.cos(a - Math.PI / 2), y2 + r * Math.sin(a - Math.PI / 2));
          ctx.arc(x2, y2, r, a - Math.PI / 2, a + Math.PI / 2);
          ctx.arc(x1, y1, r, a + Math.PI / 2, a + 1.5 * Math.PI);
          ctx.closePath();
        } else if (g.kind !== 'polygon') {
          if (lines) addLine(g, p);
        } else {
          for (let k = 0; k < g.p.length; k += 2) {
            const x = sx(p.ox + p.c * g.p[k] - p.s * g.p[k + 1]);
            const y = sy(p.oy + p.s * g.p[k] + p.c * g.p[k + 1]);
            if (k === 0) ctx.moveTo(x, y);
            else ctx.lineTo(x, y);
          }
          ctx.closePath();
        }
      }
    }

    function worldEnds(g, p) {
      const e = ends(g);
      return [p.ox + p.c * e[0] - p.s * e[1], p.oy + p.s * e[0] + p.c * e[1],
        p.ox + p.c * e[2] - p.s * e[3], p.oy + p.s * e[2] + p.c * e[3]];
    }

    // A segment, or a chain edge with a tick at its middle on the side it collides with (the
    // right of its direction; the other side lets shapes through).
    function addLine(g, p) {
      const e = worldEnds(g, p);
      ctx.moveTo(sx(e[0]), sy(e[1]));
      ctx.lineTo(sx(e[2]), sy(e[3]));
      if (g.kind !== 'edge') return;
      const dx = e[2] - e[0], dy = e[3] - e[1], len = Math.hypot(dx, dy);
      const tick = Math.min(6 * dpr / view.scale, 0.25 * len); // m: 6 px, shorter on a short edge
      const mx = 0.5 * (e[0] + e[2]), my = 0.5 * (e[1] + e[3]);
      ctx.moveTo(sx(mx), sy(my));
      ctx.lineTo(sx(mx + tick * dy / len), sy(my - tick * dx / len));
    }

    function addLines(b, p) {
      for (const g of bodies[b].geoms)
        if (g.kind === 'segment' || g.kind === 'edge') addLine(g, p);
    }

    // A circle's radius line shows its turn.
    function addSpokes(b, p) {
      for (const g of bodies[b].geoms) {
        if (g.kind !== 'circle') continue;
        const cx = p.ox + p.c * g.c[0] - p.s * g.c[1], cy = p.oy + p.s * g.c[0] + p.c * g.c[1];
        ctx.moveTo(sx(cx), sy(cy));
        ctx.lineTo(sx(cx + g.r * p.c), sy(cy + g.r * p.s));
      }
    }

    function visible(p, b) {
      const r = bodies[b].radius * view.scale + 2;
      const x = sx(p.x), y = sy(p.y);
      return x + r >= 0 && x - r <= canvas.width && y + r >= 0 && y - r <= canvas.height;
    }

    function niceStep(pixels) {
      return niceNumber(pixels / view.scale);
    }

    function drawGrid() {
      const step = niceStep(80 * dpr);
      ctx.lineWidth = 1;
      ctx.strokeStyle = '#e8ebf0';
      ctx.beginPath();
      const x0 = Math.floor(wx(0) / step) * step, x1 = wx(canvas.width);
      for (let x = x0; x <= x1; x += step) {
        const px = Math.round(sx(x)) + 0.5;
        ctx.moveTo(px, 0);
        ctx.lineTo(px, canvas.height);
      }
      const y0 = Math.floor(wy(canvas.height) / step) * step, y1 = wy(0);
      for (let y = y0; y <= y1; y += step) {
        const py = Math.round(sy(y)) + 0.5;
        ctx.moveTo(0, py);
        ctx.lineTo(canvas.width, py);
      }
      ctx.stroke();
      ctx.strokeStyle = '#d3d8e0';
      ctx.beginPath();
      ctx.moveTo(Math.round(sx(0)) + 0.5, 0);
      ctx.lineTo(Math.round(sx(0)) + 0.5, canvas.height);
      ctx.moveTo(0, Math.round(sy(0)) + 0.5);
      ctx.lineTo(canvas.width, Math.round(sy(0)) + 0.5);
      ctx.stroke();
      // Scale bar.
      const len = step * view.scale;
      const bx = 12 * dpr, by = canvas.height - 12 * dpr;
      ctx.strokeStyle = '#5b6474';
      ctx.lineWidth = 2 * dpr;
      ctx.beginPath();
      ctx.moveTo(bx, by - 4 * dpr);
      ctx.lineTo(bx, by);
      ctx.lineTo(bx + len, by);
      ctx.lineTo(bx + len, by - 4 * dpr);
      ctx.stroke();
      ctx.fillStyle = '#5b6474';
      ctx.font = 11 * dpr + 'px sans-serif';
      ctx.fillText(step + ' m', bx + len + 6 * dpr, by);
    }

    function drawBodies(poses) {
      const groups = new Map();
      for (let b = 0; b < bodies.length; b++) {
        if (!visible(poses[b], b)) continue;
        const g = bodies[b].group;
        if (!groups.has(g)) groups.set(g, []);
        groups.get(g).push(b);
      }
      ctx.lineWidth = dpr;
      ctx.lineJoin = 'round';
      for (const [g, list] of groups) {
        ctx.fillStyle = g === 'static' ? '#c9ced8' : g === 'kinematic' ? '#b7d3ea' : FILLS[g];
        ctx.strokeStyle = g === 'static' ? '#7d8696' : g === 'kinematic' ? '#4f7fa8' : STROKES[g];
        ctx.beginPath();
        for (const b of list) addBodyPath(b, poses[b], false);
        ctx.fill();
        ctx.stroke();
        ctx.beginPath();
        for (const b of list) addSpokes(b, poses[b]);
        ctx.stroke();
        // Segments and chain edges have no area: lines, drawn thicker to be seen.
        ctx.lineWidth = 2 * dpr;
        ctx.beginPath();
        for (const b of list) addLines(b, poses[b]);
        ctx.stroke();
        ctx.lineWidth = dpr;
      }
    }

    function drawJoints(joints, poses) {
      if (!joints.length) return;
      ctx.strokeStyle = '#00897b';
      ctx.fillStyle = '#00897b';
      ctx.lineWidth = 1.5 * dpr;
      const anchors = [];
      ctx.beginPath();
      for (const j of joints) {
        const pa = poses[j.a], pb = poses[j.b];
        const ax = pa.ox + pa.c * j.la[0] - pa.s * j.la[1], ay = pa.oy + pa.s * j.la[0] + pa.c * j.la[1];
        const bx = pb.ox + pb.c * j.lb[0] - pb.s * j.lb[1], by = pb.oy + pb.s * j.lb[0] + pb.c * j.lb[1];
        ctx.moveTo(sx(pa.x), sy(pa.y));
        ctx.lineTo(sx(ax), sy(ay));
        ctx.lineTo(sx(bx), sy(by));
        ctx.lineTo(sx(pb.x), sy(pb.y));
        anchors.push(sx(ax), sy(ay), sx(bx), sy(by));
      }
      ctx.stroke();
      ctx.beginPath();
      for (let k = 0; k < anchors.length; k += 2) {
        ctx.moveTo(anchors[k] + 3 * dpr, anchors[k + 1]);
        ctx.arc(anchors[k], anchors[k + 1], 3 * dpr, 0, TWO_PI);
      }
      ctx.fill();
    }

    function drawAabbs(poses) {
      ctx.strokeStyle = 'rgba(194, 24, 91, 0.7)';
      ctx.lineWidth = dpr;
      ctx.beginPath();
      for (let b = 0; b < bodies.length; b++) {
        const p = poses[b];
        if (!visible(p, b)) continue;
        for (const g of bodies[b].geoms) {
          let x0, y0, x1, y1;
          if (g.kind === 'circle') {
            const cx = p.ox + p.c * g.c[0] - p.s * g.c[1], cy = p.oy + p.s * g.c[0] + p.c * g.c[1];
            x0 = cx - g.r; x1 = cx + g.r; y0 = cy - g.r; y1 = cy + g.r;
          } else if (g.kind !== 'polygon') {
            const e = worldEnds(g, p), r = g.kind === 'capsule' ? g.r : 0;
            x0 = Math.min(e[0], e[2]) - r; x1 = Math.max(e[0], e[2]) + r;
            y0 = Math.min(e[1], e[3]) - r; y1 = Math.max(e[1], e[3]) + r;
          } else {
            x0 = y0 = Infinity; x1 = y1 = -Infinity;
            for (let k = 0; k < g.p.length; k += 2) {
              const x = p.ox + p.c * g.p[k] - p.s * g.p[k + 1], y = p.oy + p.s * g.p[k] + p.c * g.p[k + 1];
              x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
            }
          }
          ctx.rect(sx(x0), sy(y1), (x1 - x0) * view.scale, (y1 - y0) * view.scale);
        }
      }
      ctx.stroke();
    }

    // Points k0 to k1 - 1 of (px, py) with normals at angles pa.
    function drawContacts(contacts, k0, k1) {
      if (k1 === k0) return;
      ctx.strokeStyle = '#d62728';
      ctx.fillStyle = '#d62728';
      ctx.lineWidth = 1.5 * dpr;
      const len = 12 * dpr;
      ctx.beginPath();
      for (let k = k0; k < k1; k++) {
        const x = sx(contacts.px[k]), y = sy(contacts.py[k]);
        ctx.moveTo(x, y);
        ctx.lineTo(x + len * Math.cos(contacts.pa[k]), y - len * Math.sin(contacts.pa[k]));
      }
      ctx.stroke();
      ctx.beginPath();
      for (let k = k0; k < k1; k++) {
        const x = sx(contacts.px[k]), y = sy(contacts.py[k]);
        ctx.moveTo(x + 2.5 * dpr, y);
        ctx.arc(x, y, 2.5 * dpr, 0, TWO_PI);
      }
      ctx.fill();
    }

    // The outlines of the selected and hovered bodies (-1: none).
    function drawHighlight(poses, selected, hovered) {
      for (const [b, colour] of [[selected, '#1d2330'], [hovered, '#2f5d9e']]) {
        if (b < 0) continue;
        ctx.strokeStyle = colour;
        ctx.lineWidth = 2.5 * dpr;
        ctx.beginPath();
        addBodyPath(b, poses[b], true);
        ctx.stroke();
      }
    }

    // The topmost body whose shapes contain the world point (x, y), or -1; pose(b) is its pose.
    function bodyAt(pose, x, y) {
      for (let b = bodies.length - 1; b >= 0; b--) {
        const p = pose(b);
        if (Math.hypot(x - p.x, y - p.y) > bodies[b].radius) continue;
        // The point in the body frame.
        const dx = x - p.ox, dy = y - p.oy;
        const lx = p.c * dx + p.s * dy, ly = -p.s * dx + p.c * dy;
        for (const g of bodies[b].geoms) {
          if (g.kind === 'circle') {
            if (Math.hypot(lx - g.c[0], ly - g.c[1]) <= g.r) return b;
            continue;
          }
          if (g.kind !== 'polygon') {
            // Within the radius of the core segment; a line within 4 px of it.
            const e = ends(g), dx = e[2] - e[0], dy = e[3] - e[1];
            const t = Math.max(0, Math.min(1, ((lx - e[0]) * dx + (ly - e[1]) * dy) / (dx * dx + dy * dy)));
            const r = g.kind === 'capsule' ? g.r : 4 * dpr / view.scale;
            if (Math.hypot(lx - e[0] - t * dx, ly - e[1] - t * dy) <= r) return b;
            continue;
          }
          let pos = 0, neg = 0;
          const n = g.p.length;
          for (let k = 0; k < n; k += 2) {
            const ax = g.p[k], ay = g.p[k + 1], bx = g.p[(k + 2) % n], by = g.p[(k + 3) % n];
            const cross = (bx - ax) * (ly - ay) - (by - ay) * (lx - ax);
            if (cross > 0) pos++;
            else if (cross < 0) neg++;
          }
          if (pos === 0 || neg === 0) return b;
        }
      }
      return -1;
    }

    // A wheel event's zoom about the device pixel (px, py): the point under it stays where it is.
    function zoomAt(px, py, e) {
      const x = wx(px), y = wy(py);
      const delta = e.deltaY * (e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1);
      view.scale = Math.min(1e7, Math.max(1e-4, view.scale * Math.exp(-delta * 0.0015)));
      view.cx = x - (px - canvas.width / 2) / view.scale;
      view.cy = y - (canvas.height / 2 - py) / view.scale;
    }

    return {
      zoomAt,
      ctx, view, sx, sy, wx, wy, fitBox, clear, addBodyPath, visible, drawGrid, drawBodies, drawJoints,
      drawAabbs, drawContacts, drawHighlight, bodyAt,
      setBodies: (list) => { bodies = list; },
      setDpr: (d) => { dpr = d; },
    };
  }

  return { TWO_PI, BACKGROUND: '#f7f8fa', niceNumber, prepareBody, pose, create };
})();

(function () {
  'use strict';

  const $ = (id) => document.getElementById(id);
  if (!$('tamias-run')) return; // a page that draws with TamiasDraw only (the live sandbox)
  const TWO_PI = TamiasDraw.TWO_PI;
  const BACKGROUND = TamiasDraw.BACKGROUND;

  // --- decoding -------------------------------------------------------------------------
  function bytesOf(b64) {
    const s = atob(b64);
    const a = new Uint8Array(s.length);
    for (let i = 0; i < s.length; i++) a[i] = s.charCodeAt(i);
    return a;
  }

  // Unsigned varints, 7 bits a byte, low bits first; arithmetic (not bit operations) keeps
  // them exact up to 2^53.
  function Reader(bytes) {
    this.b = bytes;
    this.i = 0;
  }
  Reader.prototype.varint = function () {
    let v = 0, m = 1, byte;
    do {
      if (this.i >= this.b.length) throw new Error('the recorded data is truncated');
      byte = this.b[this.i++];
      v += (byte & 127) * m;
      m *= 128;
    } while (byte & 128);
    return v;
  };
  Reader.prototype.byte = function () {
    if (this.i >= this.b.length) throw new Error('the recorded data is truncated');
    return this.b[this.i++];
  };
  const unzigzag = (z) => (z % 2 === 0 ? z / 2 : -(z + 1) / 2);

  // The streams are raw DEFLATE (view_deflate.hpp), inflated by the browser itself.
  async function inflate(b64) {
    const stream = new Blob([bytesOf(b64)]).stream().pipeThrough(new DecompressionStream('deflate-raw'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }

  // One channel, frame by frame and body by body: the residual from the body's linear
  // extrapolation of its two previous frames, zigzag-coded; a 0 token is followed by the
  // length less one of a run of zero residuals (ResidualStream in view_html.hpp). The result
  // is the quantised value: multiply by the channel's quantum.
  function decodeChannel(bytes, frames, bodies) {
    const r = new Reader(bytes);
    const n = new Float64Array(frames * bodies);
    let zeros = 0;
    for (let i = 0; i < n.length; i++) {
      let d = 0;
      if (zeros > 0) {
        zeros--;
      } else {
        const z = r.varint();
        if (z === 0) zeros = r.varint();
        else d = unzigzag(z);
      }
      if (i < bodies) n[i] = d;
      else if (i < 2 * bodies) n[i] = n[i - bodies] + d;
      else n[i] = 2 * n[i - bodies] - n[i - 2 * bodies] + d;
    }
    if (r.i !== r.b.length) throw new Error('the recorded data has trailing bytes');
    return n;
  }

  // Contact points: per frame a count, then per point its position in steps and its normal in
  // 256ths of a turn, each against the previous frame's point at the same place (or else the
  // point before it in this frame), the normal modulo 256.
  function decodeContacts(c, bytes, frames) {
    const start = new Int32Array(frames + 1);
    const px = new Float64Array(c.points), py = new Float64Array(c.points);
    const pa = new Float64Array(c.points);
    if (!c.recorded) return { start, px, py, pa };
    const r = new Reader(bytes);
    const q = D.quantum.contact;
    let last = [], k = 0;
    for (let f = 0; f < frames; f++) {
      start[f] = k;
      const count = r.varint(), current = [];
      for (let j = 0; j < count; j++, k++) {
        const p = j < last.length ? last[j] : j > 0 ? current[j - 1] : [0, 0, 0];
        const x = p[0] + unzigzag(r.varint()), y = p[1] + unzigzag(r.varint());
        const code = (p[2] + r.byte()) % 256;
        current.push([x, y, code]);
        px[k] = x * q;
        py[k] = y * q;
        pa[k] = (code / 256) * TWO_PI;
      }
      last = current;
    }
    start[frames] = k;
    if (k !== c.points || r.i !== r.b.length) throw new Error('the contact data does not match its count');
    return { start, px, py, pa };
  }

  const CHANNELS = ['x', 'y', 'phi', 'vx', 'vy', 'omega'];
  let D, F, B, Q, ch, contacts, bodies;
  async function load() {
    D = JSON.parse($('tamias-run').textContent);
    if (D.format !== 1 || D.encoding !== 'deflate-raw') throw new Error('unknown data format');
    if (typeof DecompressionStream === 'undefined')
      throw new Error('this browser has no DecompressionStream (Chrome 103, Firefox 113, Safari 16.4 and later have it)');
    F = D.frames.step.length;
    B = D.bodies.length;
    Q = D.quantum;
    const streams = await Promise.all(CHANNELS.map((k) => inflate(D.channels[k])));
    ch = {};
    CHANNELS.forEach((k, i) => { ch[k] = decodeChannel(streams[i], F, B); });
    contacts = decodeContacts(D.contacts, D.contacts.recorded ? await inflate(D.contacts.data) : null, F);
  }
  // The page's state as an attribute of <html> too (data-tamias-player: decoding, ready or
  // error), so that a tool that sees only the DOM (chromium --dump-dom) can tell whether a
  // screenshot taken at the same moment shows the run: it is decoded after the page has loaded.
  const setStatus = (status) => { document.documentElement.dataset.tamiasPlayer = status; };
  window.tamiasPlayer = { ready: false };
  const loadStart = performance.now();
  $('message').textContent = 'Decoding the run\u2026';
  setStatus('decoding');
  load().then(start).catch((e) => {
    $('message').textContent = 'This page cannot show its run: ' + e.message;
    window.tamiasPlayer = { ready: false, error: String(e) };
    setStatus('error');
  });

  function start() {
    $('message').textContent = '';

    bodies = D.bodies.map((b, i) => TamiasDraw.prepareBody({ ...b, geoms: b.shapes.map((s) => D.geoms[s]) }, i));
    const movingIds = [];
    bodies.forEach((b, i) => { if (b.type !== 'static') movingIds.push(i); });

    // The body's recorded state in SI units (phi wrapped to [0, 2 pi), as `tamias2d run` writes).
    function state(f, b) {
      const i = f * B + b;
      let phi = (ch.phi[i] * Q.angle) % TWO_PI;
      if (phi < 0) phi += TWO_PI;
      return {
        step: D.frames.step[f], time: D.frames.time[f],
        x: ch.x[i] * Q.position, y: ch.y[i] * Q.position, phi,
        vx: ch.vx[i] * Q.velocity, vy: ch.vy[i] * Q.velocity, omega: ch.omega[i] * Q.angular_velocity,
      };
    }

    // The body frame at frame f: origin and rotation (the recorded state is the centre of mass).
    function pose(f, b) {
      const i = f * B + b;
      return TamiasDraw.pose(ch.x[i] * Q.position, ch.y[i] * Q.position, ch.phi[i] * Q.angle, bodies[b].lc);
    }

    // --- view -----------------------------------------------------------------------------
    const canvas = $('view');
    const drawing = TamiasDraw.create(canvas);
    drawing.setBodies(bodies);
    const { ctx, view, sx, sy, wx, wy } = drawing; // view.scale: device pixels per metre
    const stage = $('stage');
    let dpr = window.devicePixelRatio || 1;
    let fitted = false;

    function fit() {
      const b = D.bounds.moving || D.bounds.all;
      if (!b || canvas.width === 0) return;
      drawing.fitBox(b);
      fitted = true;
      dirty = true;
    }

    function resize() {
      dpr = window.devicePixelRatio || 1;
      drawing.setDpr(dpr);
      const w = Math.max(1, Math.round(stage.clientWidth * dpr));
      const h = Math.max(1, Math.round(stage.clientHeight * dpr));
      if (canvas.width !== w || canvas.height !== h) {
        canvas.width = w;
        canvas.height = h;
        if (!fitted) fit();
        dirty = true;
      }
      const e = $('energy');
      const ew = Math.max(1, Math.round(e.clientWidth * dpr)), eh = Math.max(1, Math.round(e.clientHeight * dpr));
      if (e.width !== ew || e.height !== eh) {
        e.width = ew;
        e.height = eh;
        dirty = true;
      }
    }

    // --- state of the player --------------------------------------------------------------
    let frame = 0, playing = false, simTime = D.frames.time[0] || 0, lastNow = null, dirty = true;
    let hovered = -1, selected = -1, mouse = null;
    const show = { contacts: false, aabbs: false, velocities: false, trails: false, joints: true };

    // Velocity arrows: v times a round number of seconds, so that the fastest body's arrow is
    // about a tenth of the scene.
    let vmax = 0;
    for (let i = 0; i < F * B; i++) vmax = Math.max(vmax, Math.abs(ch.vx[i]), Math.abs(ch.vy[i]));
    vmax *= Q.velocity;
    const velocityScale = (() => {
      const b = D.bounds.moving || D.bounds.all;
      const size = b ? Math.hypot(b[2] - b[0], b[3] - b[1]) : 1;
      return vmax > 0 ? TamiasDraw.niceNumber((0.1 * size) / vmax) : 0.1;
    })();
    $('velocity-scale').textContent = '(v \u00d7 ' + velocityScale + ' s)';

    function drawTrails(f) {
      if (movingIds.length === 0) return;
      const length = Math.max(2, Math.min(240, Math.floor(60000 / movingIds.length)));
      const first = Math.max(0, f - length);
      ctx.strokeStyle = 'rgba(47, 93, 158, 0.45)';
      ctx.lineWidth = dpr;
      ctx.beginPath();
      for (const b of movingIds) {
        for (let g = first; g <= f; g++) {
          const x = sx(ch.x[g * B + b] * Q.position), y = sy(ch.y[g * B + b] * Q.position);
          if (g === first) ctx.moveTo(x, y);
          else ctx.lineTo(x, y);
        }
      }
      ctx.stroke();
    }

    function drawVelocities(f) {
      ctx.strokeStyle = '#2e7d32';
      ctx.lineWidth = 1.5 * dpr;
      ctx.beginPath();
      const head = 5 * dpr;
      for (const b of movingIds) {
        const i = f * B + b;
        const x = sx(ch.x[i] * Q.position), y = sy(ch.y[i] * Q.position);
        const dx = ch.vx[i] * Q.velocity * velocityScale * view.scale;
        const dy = -ch.vy[i] * Q.velocity * velocityScale * view.scale;
        const len = Math.hypot(dx, dy);
        if (len < 1) continue;
        ctx.moveTo(x, y);
        ctx.lineTo(x + dx, y + dy);
        const ux = dx / len, uy = dy / len;
        ctx.moveTo(x + dx - head * (ux - 0.5 * uy), y + dy - head * (uy + 0.5 * ux));
        ctx.lineTo(x + dx, y + dy);
        ctx.lineTo(x + dx - head * (ux + 0.5 * uy), y + dy - head * (uy - 0.5 * ux));
      }
      ctx.stroke();
    }

    const fmt = (v, d) => (Math.abs(v) < 0.5 * Math.pow(10, -d) ? 0 : v).toFixed(d);

    function showBody(f) {
      const b = selected >= 0 ? selected : hovered;
      const box = $('body-info');
      if (b < 0) {
        box.innerHTML = '<p class="mute">Point at a body to see its state; click to keep it.</p>';
        return;
      }
      const s = state(f, b), body = bodies[b];
      const row = (k, v, u) => '<tr><td>' + k + '</td><td class="v">' + v + '</td><td>' + u + '</td></tr>';
      const name = document.createElement('div');
      name.className = 'name';
      name.textContent = (body.name || '(unnamed)') + '  #' + b + ', ' + body.type + (b === selected ? ', selected' : '');
      box.innerHTML = '<table>' +
        row('x', fmt(s.x, 4), 'm') + row('y', fmt(s.y, 4), 'm') +
        row('v<sub>x</sub>', fmt(s.vx, 3), 'm/s') + row('v<sub>y</sub>', fmt(s.vy, 3), 'm/s') +
        row('|v|', fmt(Math.hypot(s.vx, s.vy), 3), 'm/s') +
        row('&phi;', fmt(s.phi, 4), 'rad (' + fmt((s.phi * 180) / Math.PI, 2) + '&deg;)') +
        row('&omega;', fmt(s.omega, 3), 'rad/s') +
        (body.type === 'dynamic' ? row('m', +body.mass.toPrecision(6), 'kg') + row('I', +body.inertia.toPrecision(6), 'kg m&sup2;') : '') +
        '</table>';
      box.insertBefore(name, box.firstChild);
    }

    function drawEnergy(f) {
      const e = $('energy'), g = e.getContext('2d');
      const W = e.width, H = e.height, pad = 4 * dpr;
      g.clearRect(0, 0, W, H);
      const k = D.frames.kinetic, p = D.frames.potential, t = D.frames.time;
      let lo = Infinity, hi = -Infinity;
      for (let i = 0; i < F; i++) {
        for (const v of [k[i], p[i], k[i] + p[i]]) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      }
      if (!(hi > lo)) { hi = lo + 1; lo -= 1; }
      const t0 = t[0], t1 = F > 1 ? t[F - 1] : t0 + 1;
      const X = (v) => pad + ((v - t0) / (t1 - t0 || 1)) * (W - 2 * pad);
      const Y = (v) => H - pad - ((v - lo) / (hi - lo)) * (H - 2 * pad);
      if (lo < 0 && hi > 0) {
        g.strokeStyle = '#dde2ea';
        g.lineWidth = dpr;
        g.beginPath(); g.moveTo(pad, Y(0)); g.lineTo(W - pad, Y(0)); g.stroke();
      }
      for (const [series, colour] of [[(i) => k[i], '#d9822b'], [(i) => p[i], '#2f6fb0'], [(i) => k[i] + p[i], '#1d2330']]) {
        g.strokeStyle = colour;
        g.lineWidth = 1.5 * dpr;
        g.beginPath();
        for (let i = 0; i < F; i++) {
          if (i === 0) g.moveTo(X(t[i]), Y(series(i)));
          else g.lineTo(X(t[i]), Y(series(i)));
        }
        g.stroke();
      }
      g.strokeStyle = '#c62828';
      g.lineWidth = dpr;
      g.beginPath(); g.moveTo(X(t[f]), pad); g.lineTo(X(t[f]), H - pad); g.stroke();
      const num = (v) => (Math.abs(v) >= 1e5 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : v.toFixed(4));
      $('energy-now').innerHTML = '<span class="k">' + num(k[f]) + '</span> + <span class="p">' + num(p[f]) +
        '</span> = <b>' + num(k[f] + p[f]) + '</b> J';
    }

    function draw() {
      dirty = false;
      resize();
      dirty = false;
      const f = frame;
      drawing.clear(BACKGROUND);
      drawing.drawGrid();
      const poses = new Array(B);
      for (let b = 0; b < B; b++) poses[b] = pose(f, b);
      if (show.trails) drawTrails(f);
      drawing.drawBodies(poses);
      if (show.joints) drawing.drawJoints(D.joints, poses);
      if (show.aabbs) drawing.drawAabbs(poses);
      if (show.velocities) drawVelocities(f);
      if (show.contacts) drawing.drawContacts(contacts, contacts.start[f], contacts.start[f + 1]);
      hovered = mouse ? drawing.bodyAt((b) => pose(f, b), wx(mouse.x * dpr), wy(mouse.y * dpr)) : -1;
      drawing.drawHighlight(poses, selected, hovered);
      showBody(f);
      drawEnergy(f);
      const t = D.frames.time[f];
      $('clock').textContent = 't = ' + t.toFixed(4) + ' s \u00b7 step ' + D.frames.step[f] + ' / ' +
        D.frames.step[F - 1] + ' \u00b7 frame ' + f + ' / ' + (F - 1);
      $('scrub').value = String(f);
      $('play').innerHTML = playing ? '&#10074;&#10074;' : '&#9654;';
    }

    // --- control --------------------------------------------------------------------------
    function setFrame(f) {
      frame = Math.max(0, Math.min(F - 1, Math.round(f)));
      simTime = D.frames.time[frame];
      dirty = true;
    }
    function play() {
      if (F < 2) return;
      if (frame === F - 1) setFrame(0);
      playing = true;
      lastNow = null;
      dirty = true;
    }
    function pause() {
      playing = false;
      dirty = true;
    }

    function tick(now) {
      if (playing) {
        if (lastNow !== null) simTime += ((now - lastNow) / 1000) * Number($('speed').value);
        lastNow = now;
        const times = D.frames.time, end = times[F - 1];
        let f = frame;
        while (f + 1 < F && times[f + 1] <= simTime) f++;
        if (f !== frame) {
          frame = f;
          dirty = true;
        }
        // At the end: hold the final state for half a second, then loop or stop.
        if (simTime > end + 0.5 * Number($('speed').value)) {
          if ($('loop').checked) setFrame(0);
          else pause();
        }
      }
      if (dirty) draw();
      requestAnimationFrame(tick);
    }

    $('scrub').max = String(F - 1);
    $('scrub').addEventListener('input', (e) => setFrame(Number(e.target.value)));
    $('play').addEventListener('click', () => (playing ? pause() : play()));
    $('back').addEventListener('click', () => { pause(); setFrame(frame - 1); });
    $('fwd').addEventListener('click', () => { pause(); setFrame(frame + 1); });
    for (const box of document.querySelectorAll('[data-toggle]')) {
      const name = box.dataset.toggle;
      box.checked = show[name];
      box.addEventListener('change', () => { show[name] = box.checked; dirty = true; });
    }
    function disable(name, why) {
      const box = document.querySelector('[data-toggle="' + name + '"]');
      box.disabled = true;
      box.parentElement.classList.add('disabled');
      box.parentElement.title = why;
    }
    if (!D.contacts.recorded) {
      disable('contacts', D.contacts.limit === 0 ? 'not recorded (--max-contacts 0)' :
        'not recorded: the run has more than ' + D.contacts.limit + ' contact points (--max-contacts)');
    }
    if (!D.joints.length) disable('joints', 'the scene has no joints');

    document.addEventListener('keydown', (e) => {
      const tag = e.target.tagName;
      if ((tag === 'INPUT' && e.target.type !== 'range' && e.target.type !== 'checkbox') || tag === 'SELECT') return;
      if (tag === 'BUTTON' && (e.key === ' ' || e.key === 'Enter')) return; // the button's own click
      if (e.key === ' ') { playing ? pause() : play(); }
      else if (e.key === 'ArrowLeft') { pause(); setFrame(frame - 1); }
      else if (e.key === 'ArrowRight') { pause(); setFrame(frame + 1); }
      else if (e.key === 'Home') { setFrame(0); }
      else if (e.key === 'End') { setFrame(F - 1); }
      else if (e.key === 'f' || e.key === 'F') { fit(); }
      else return;
      e.preventDefault();
    });

    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const r = canvas.getBoundingClientRect();
      drawing.zoomAt((e.clientX - r.left) * dpr, (e.clientY - r.top) * dpr, e);
      dirty = true;
    }, { passive: false });

    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY, cx: view.cx, cy: view.cy, moved: false };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      const r = canvas.getBoundingClientRect();
      mouse = { x: e.clientX - r.left, y: e.clientY - r.top };
      if (drag) {
        const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
        if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
        if (drag.moved) {
          canvas.classList.add('dragging');
          view.cx = drag.cx - (dx * dpr) / view.scale;
          view.cy = drag.cy + (dy * dpr) / view.scale;
        }
      }
      dirty = true;
    });
    canvas.addEventListener('pointerup', (e) => {
      if (drag && !drag.moved) {
        const r = canvas.getBoundingClientRect();
        const b = drawing.bodyAt((k) => pose(frame, k), wx((e.clientX - r.left) * dpr), wy((e.clientY - r.top) * dpr));
        selected = b === selected ? -1 : b;
      }
      drag = null;
      canvas.classList.remove('dragging');
      dirty = true;
    });
    canvas.addEventListener('pointerleave', () => { mouse = null; dirty = true; });
    canvas.addEventListener('dblclick', fit);
    if (window.ResizeObserver) new ResizeObserver(() => { dirty = true; }).observe(stage);
    window.addEventListener('resize', () => { dirty = true; });

    $('description').textContent = D.description || '';
    $('meta').textContent = B + ' bodies, ' + D.joints.length + ' joints; ' + F + ' frames, every ' +
      (D.every === 1 ? 'step' : D.every + ' steps') + ' of ' + +D.dt.toPrecision(6) + ' s; states to ' + Q.position + ' m, ' + Q.angle + ' rad, ' +
      Q.velocity + ' m/s, ' + Q.angular_velocity + ' rad/s; contacts: ' +
      (D.contacts.recorded ? D.contacts.points + ' points' : 'not recorded') + '.';

    // Options in the address: #play, #frame=N, #speed=X, #show=trails,contacts.
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      const [key, value] = part.split('=');
      if (key === 'frame') setFrame(Number(value) || 0);
      else if (key === 'speed') $('speed').value = value;
      else if (key === 'show') {
        for (const name of (value || '').split(',')) {
          if (name in show) {
            show[name] = true;
            const box = document.querySelector('[data-toggle="' + name + '"]');
            if (box) box.checked = true;
          }
        }
      }
    }

    window.tamiasPlayer = {
      ready: true,
      decodeMs: performance.now() - loadStart, // page script start to decoded run
      frameCount: F,
      bodyCount: B,
      quantum: Q,
      background: BACKGROUND,
      name: (b) => bodies[b].name,
      type: (b) => bodies[b].type,
      radius: (b) => bodies[b].radius, // m, about the centre of mass, holding every shape
      state,
      energy: (f) => ({ kinetic: D.frames.kinetic[f], potential: D.frames.potential[f], total: D.frames.kinetic[f] + D.frames.potential[f] }),
      contactCount: (f) => contacts.start[f + 1] - contacts.start[f],
      frame: () => frame,
      setFrame: (f) => { setFrame(f); draw(); },
      play,
      pause: () => { pause(); draw(); },
      playing: () => playing,
      show: (name, on) => {
        show[name] = !!on;
        const box = document.querySelector('[data-toggle="' + name + '"]');
        if (box) box.checked = show[name];
        draw();
      },
      fit: () => { fit(); draw(); },
      render: draw,
      hovered: () => hovered, // the body under the cursor, -1 for none
      view: () => ({ cx: view.cx, cy: view.cy, scale: view.scale / dpr }), // scale: CSS px per m
      // A world point's position in the page (CSS pixels from the viewport's top left).
      toScreen: (x, y) => {
        const r = canvas.getBoundingClientRect();
        return { x: r.left + sx(x) / dpr, y: r.top + sy(y) / dpr };
      },
    };
    if (/(^|[#&])play(&|$)/.test(location.hash)) play();
    draw();
    setStatus('ready'); // drawn: a screenshot from now on shows the run
    requestAnimationFrame(tick);
  }
})();
