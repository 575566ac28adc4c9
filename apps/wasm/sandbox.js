// The live sandbox (docs/viewer.md, "Live sandbox"): the library compiled to WebAssembly
// (apps/wasm/sandbox_bindings.cpp) steps an example scene in the page, drawn with the player's
// drawing code (TamiasDraw, apps/cli/player/player.js). window.tamiasSandbox is for tests and
// the browser's console.
(function () {
  'use strict';

  const $ = (id) => document.getElementById(id);
  const TD = window.TamiasDraw;
  const SCENES = JSON.parse($('tamias-scenes').textContent); // file name -> scene text
  const MAX_STEPS_PER_FRAME = 4; // behind real time rather than frozen when a step is slow

  window.tamiasSandbox = { ready: false };
  $('message').textContent = 'Starting the engine\u2026';

  createTamiasSandbox().then(start).catch((e) => {
    $('message').textContent = 'The engine did not start: ' + e;
    window.tamiasSandbox = { ready: false, error: String(e) };
  });

  function start(M) {
    $('message').textContent = '';
    const api = {
      error: M.cwrap('tamias_error', 'string', []),
      text: M.cwrap('tamias_text', 'string', []),
      load: M.cwrap('tamias_load', 'number', ['string', 'string']),
      step: M.cwrap('tamias_step', 'number', ['number']),
      count: M.cwrap('tamias_body_count', 'number', []),
      time: M.cwrap('tamias_time', 'number', []),
      states: M.cwrap('tamias_states', 'number', []),
      hash: M.cwrap('tamias_state_hash', 'string', []),
      gravity: M.cwrap('tamias_set_gravity', null, ['number', 'number']),
      restitution: M.cwrap('tamias_set_restitution', null, ['number']),
      addBox: M.cwrap('tamias_add_box', 'number', ['number', 'number', 'number', 'number']),
      addCircle: M.cwrap('tamias_add_circle', 'number', ['number', 'number', 'number']),
      grab: M.cwrap('tamias_grab', 'number', ['number', 'number', 'number', 'number']),
      drag: M.cwrap('tamias_drag', 'number', ['number', 'number']),
      release: M.cwrap('tamias_release', null, []),
    };

    const canvas = $('view');
    const stage = $('stage');
    const drawing = TD.create(canvas);
    const { view, sx, sy, wx, wy } = drawing;
    let dpr = window.devicePixelRatio || 1;
    let scene = null, sceneName = '', bodies = [], joints = [], poses = [], S = new Float64Array(0);
    let steps = 0, running = false, lastNow = null, debt = 0, dirty = true, fitted = false;
    let mouse = null, hovered = -1, grabbed = -1, grabPoint = null, drag = null, message = '';

    // Every body's state, as World::state gives it: x, y, phi, vx, vy, omega (copied out of the
    // module's memory, which may move when it grows).
    function readStates() {
      const n = api.count();
      const p = api.states() / 8;
      S = M.HEAPF64.slice(p, p + 6 * n);
      poses = new Array(n);
      for (let b = 0; b < n; b++) poses[b] = TD.pose(S[6 * b], S[6 * b + 1], S[6 * b + 2], bodies[b].lc);
    }

    function fail(what) {
      message = what + ': ' + api.error();
      $('message').textContent = message;
      running = false;
      return false;
    }

    function load(name) {
      if (!(name in SCENES)) throw new Error('no scene ' + name);
      const r = $('restitution').value;
      api.restitution(r === '' ? -1 : Math.min(1, Math.max(0, Number(r))));
      if (api.load(SCENES[name], name) < 0) return fail(name);
      message = '';
      $('message').textContent = '';
      scene = JSON.parse(api.text());
      sceneName = name;
      bodies = scene.bodies.map((b, i) => TD.prepareBody(b, i));
      joints = scene.joints;
      drawing.setBodies(bodies);
      steps = 0;
      grabbed = -1;
      $('scene').value = name;
      $('gx').value = String(scene.gravity[0]);
      $('gy').value = String(scene.gravity[1]);
      $('description').textContent = scene.description || '';
      readStates();
      fit();
      dirty = true;
      return true;
    }

    // The moving bodies' extent (all bodies' when none moves).
    function fit() {
      let box = null;
      for (const pass of ['moving', 'all']) {
        for (let b = 0; b < bodies.length; b++) {
          if (pass === 'moving' && bodies[b].type === 'static') continue;
          const r = bodies[b].radius, x = S[6 * b], y = S[6 * b + 1];
          if (!box) box = [x - r, y - r, x + r, y + r];
          else box = [Math.min(box[0], x - r), Math.min(box[1], y - r), Math.max(box[2], x + r), Math.max(box[3], y + r)];
        }
        if (box) break;
      }
      if (box && canvas.width > 0) {
        drawing.fitBox(box);
        fitted = true;
      }
      dirty = true;
    }

    function step(n) {
      if (api.step(n) < 0) return fail('step ' + (steps + 1));
      steps += n;
      if (grabbed >= 0 && grabPoint) api.drag(grabPoint.x, grabPoint.y);
      readStates();
      dirty = true;
      return true;
    }

    function drop(kind, x, y) {
      const b = kind === 'circle' ? api.addCircle(x, y, 0.5) : api.addBox(x, y, 1, 1);
      if (b < 0) return fail('drop');
      bodies.push(TD.prepareBody(JSON.parse(api.text()), b));
      readStates();
      dirty = true;
      return b;
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
    }

    const fmt = (v, d) => (Math.abs(v) < 0.5 * Math.pow(10, -d) ? 0 : v).toFixed(d);
    function showBody() {
      const b = grabbed >= 0 ? grabbed : hovered;
      const box = $('body-info');
      if (b < 0 || b >= bodies.length) {
        box.innerHTML = '<p class="mute">Drag a body to pull it (a target joint, DD21).</p>';
        return;
      }
      const s = S.subarray(6 * b, 6 * b + 6);
      const row = (k, v, u) => '<tr><td>' + k + '</td><td class="v">' + v + '</td><td>' + u + '</td></tr>';
      const name = document.createElement('div');
      name.className = 'name';
      name.textContent = (bodies[b].name || '(unnamed)') + '  #' + b + ', ' + bodies[b].type + (b === grabbed ? ', pulled' : '');
      box.innerHTML = '<table>' + row('x', fmt(s[0], 4), 'm') + row('y', fmt(s[1], 4), 'm') +
        row('v<sub>x</sub>', fmt(s[3], 3), 'm/s') + row('v<sub>y</sub>', fmt(s[4], 3), 'm/s') +
        row('&phi;', fmt(s[2], 4), 'rad') + row('&omega;', fmt(s[5], 3), 'rad/s') + '</table>';
      box.insertBefore(name, box.firstChild);
    }

    function draw() {
      resize();
      dirty = false;
      drawing.clear(TD.BACKGROUND);
      drawing.drawGrid();
      if (!scene) return;
      drawing.drawBodies(poses);
      drawing.drawJoints(joints, poses);
      if (grabbed >= 0 && grabPoint) { // the target joint: the body's centre to the cursor
        const ctx = drawing.ctx, p = poses[grabbed];
        ctx.strokeStyle = '#c62828';
        ctx.lineWidth = 1.5 * dpr;
        ctx.beginPath();
        ctx.moveTo(sx(p.x), sy(p.y));
        ctx.lineTo(sx(grabPoint.x), sy(grabPoint.y));
        ctx.stroke();
      }
      hovered = mouse ? drawing.bodyAt((b) => poses[b], wx(mouse.x * dpr), wy(mouse.y * dpr)) : -1;
      drawing.drawHighlight(poses, grabbed, hovered);
      showBody();
      $('clock').textContent = 't = ' + api.time().toFixed(4) + ' s \u00b7 step ' + steps;
      $('play').innerHTML = running ? '&#10074;&#10074;' : '&#9654;';
      $('status').textContent = bodies.length + ' bodies, dt = ' + +scene.dt.toPrecision(6) + ' s';
    }

    function tick(now) {
      if (running && scene) {
        if (lastNow !== null) debt += (now - lastNow) / 1000;
        lastNow = now;
        let n = Math.floor(debt / scene.dt);
        if (n > MAX_STEPS_PER_FRAME) { n = MAX_STEPS_PER_FRAME; debt = 0; }
        if (n > 0) {
          debt -= n * scene.dt;
          step(n);
        }
      }
      if (dirty) draw();
      requestAnimationFrame(tick);
    }

    function play() { running = true; lastNow = null; debt = 0; dirty = true; }
    function pause() { running = false; dirty = true; }

    // --- controls ---------------------------------------------------------------------------
    for (const name of Object.keys(SCENES)) {
      const o = document.createElement('option');
      o.value = name;
      o.textContent = name.replace(/\.json$/, '');
      $('scene').appendChild(o);
    }
    $('scene').addEventListener('change', (e) => load(e.target.value));
    $('play').addEventListener('click', () => (running ? pause() : play()));
    $('fwd').addEventListener('click', () => { pause(); step(1); });
    $('reset').addEventListener('click', () => load(sceneName));
    for (const id of ['gx', 'gy']) {
      $(id).addEventListener('change', () => {
        const gx = Number($('gx').value), gy = Number($('gy').value);
        if (Number.isFinite(gx) && Number.isFinite(gy)) {
          api.gravity(gx, gy);
          if (api.error()) fail('gravity');
        }
      });
    }
    $('restitution').addEventListener('change', () => {
      const r = $('restitution').value;
      api.restitution(r === '' ? -1 : Math.min(1, Math.max(0, Number(r))));
    });

    document.addEventListener('keydown', (e) => {
      const tag = e.target.tagName;
      if (tag === 'INPUT' || tag === 'SELECT') return;
      if (tag === 'BUTTON' && (e.key === ' ' || e.key === 'Enter')) return;
      if (e.key === ' ') { running ? pause() : play(); }
      else if (e.key === 'ArrowRight') { pause(); step(1); }
      else if (e.key === 'r' || e.key === 'R') { load(sceneName); }
      else if (e.key === 'f' || e.key === 'F') { fit(); }
      else if ((e.key === 'b' || e.key === 'B' || e.key === 'c' || e.key === 'C') && mouse) {
        drop(e.key.toLowerCase() === 'c' ? 'circle' : 'box', wx(mouse.x * dpr), wy(mouse.y * dpr));
      } else return;
      e.preventDefault();
    });

    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const r = canvas.getBoundingClientRect();
      drawing.zoomAt((e.clientX - r.left) * dpr, (e.clientY - r.top) * dpr, e);
      dirty = true;
    }, { passive: false });

    // A press on a dynamic body grabs it with a target joint that follows the cursor; on
    // anything else it pans the view, and a click without moving drops the chosen shape.
    canvas.addEventListener('pointerdown', (e) => {
      const r = canvas.getBoundingClientRect();
      const x = wx((e.clientX - r.left) * dpr), y = wy((e.clientY - r.top) * dpr);
      const b = drawing.bodyAt((k) => poses[k], x, y);
      canvas.setPointerCapture(e.pointerId);
      if (b >= 0 && bodies[b].type === 'dynamic') {
        if (api.grab(b, x, y, 1000) < 0) return fail('grab');
        grabbed = b;
        grabPoint = { x, y };
        drag = null;
      } else {
        drag = { x: e.clientX, y: e.clientY, cx: view.cx, cy: view.cy, moved: false, wx: x, wy: y };
      }
      dirty = true;
    });
    canvas.addEventListener('pointermove', (e) => {
      const r = canvas.getBoundingClientRect();
      mouse = { x: e.clientX - r.left, y: e.clientY - r.top };
      if (grabbed >= 0) {
        grabPoint = { x: wx(mouse.x * dpr), y: wy(mouse.y * dpr) };
        api.drag(grabPoint.x, grabPoint.y);
      } else if (drag) {
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
    canvas.addEventListener('pointerup', () => {
      if (grabbed >= 0) {
        api.release();
        grabbed = -1;
        grabPoint = null;
      } else if (drag && !drag.moved && $('tool').value !== 'none') {
        drop($('tool').value, drag.wx, drag.wy);
      }
      drag = null;
      canvas.classList.remove('dragging');
      dirty = true;
    });
    canvas.addEventListener('pointerleave', () => { mouse = null; dirty = true; });
    canvas.addEventListener('dblclick', fit);
    if (window.ResizeObserver) new ResizeObserver(() => { dirty = true; }).observe(stage);
    window.addEventListener('resize', () => { dirty = true; });

    // Options in the address: #scene=pyramid20.json, #play.
    let first = SCENES['pyramid20.json'] ? 'pyramid20.json' : Object.keys(SCENES)[0];
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      const [key, value] = part.split('=');
      if (key === 'scene' && value in SCENES) first = value;
    }
    resize();
    load(first);

    const hex = (v) => {
      const b = new DataView(new ArrayBuffer(8));
      b.setFloat64(0, v);
      return b.getBigUint64(0).toString(16).padStart(16, '0');
    };
    window.tamiasSandbox = {
      ready: true,
      scenes: Object.keys(SCENES),
      background: TD.BACKGROUND,
      load: (name) => { const ok = load(name); draw(); return ok; },
      error: () => message,
      step: (n) => { const ok = step(n); draw(); return ok; },
      steps: () => steps,
      time: () => api.time(),
      bodyCount: () => bodies.length,
      name: (b) => bodies[b].name,
      type: (b) => bodies[b].type,
      radius: (b) => bodies[b].radius,
      // The body's state: x, y, phi, vx, vy, omega as numbers and as the doubles' bits in hex.
      state: (b) => {
        const s = Array.from(S.subarray(6 * b, 6 * b + 6));
        return { x: s[0], y: s[1], phi: s[2], vx: s[3], vy: s[4], omega: s[5], hex: s.map(hex) };
      },
      states: () => Array.from(S),
      stateHash: () => api.hash(),
      setGravity: (gx, gy) => { $('gx').value = String(gx); $('gy').value = String(gy); api.gravity(gx, gy); },
      drop: (kind, x, y) => { const b = drop(kind, x, y); draw(); return b; },
      play,
      pause: () => { pause(); draw(); },
      running: () => running,
      grabbed: () => grabbed,
      fit: () => { fit(); draw(); },
      render: draw,
      toScreen: (x, y) => {
        const r = canvas.getBoundingClientRect();
        return { x: r.left + sx(x) / dpr, y: r.top + sy(y) / dpr };
      },
    };
    if (/(^|[#&])play(&|$)/.test(location.hash)) play();
    draw();
    requestAnimationFrame(tick);
  }
})();
