// kinsyn's 3D view of a manipulator (docs/view.md). The page's data (the element
// `kinsyn-data`) holds the mechanism and configurations as joint values, all computed by
// kinsyn; this script computes each body's displacement from joint values by the product of
// exponentials along the mechanism's spanning tree (as kinsyn's Mechanism::poses does) and
// draws the result with three.js.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('kinsyn-data').textContent);
  const scene = data.scene;
  const s = scene.scale > 0 ? scene.scale : 1;

  // ---- Kinematics: rigid displacements {r: row-major 3x3, t: [x, y, z]}.
  function rotation(axis, angle) {
    const [x, y, z] = axis;
    const c = Math.cos(angle), n = Math.sin(angle), k = 1 - c;
    return [c + x * x * k, x * y * k - z * n, x * z * k + y * n,
      y * x * k + z * n, c + y * y * k, y * z * k - x * n,
      z * x * k - y * n, z * y * k + x * n, c + z * z * k];
  }
  function apply(r, v) {
    return [r[0] * v[0] + r[1] * v[1] + r[2] * v[2],
      r[3] * v[0] + r[4] * v[1] + r[5] * v[2],
      r[6] * v[0] + r[7] * v[1] + r[8] * v[2]];
  }
  function product(a, b) {
    const out = new Array(9);
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) {
        out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
      }
    }
    return out;
  }
  function compose(a, b) {
    const t = apply(a.r, b.t);
    return { r: product(a.r, b.r), t: [t[0] + a.t[0], t[1] + a.t[1], t[2] + a.t[2]] };
  }
  const IDENTITY = { r: [1, 0, 0, 0, 1, 0, 0, 0, 1], t: [0, 0, 0] };
  // The displacement of a joint's `to` body relative to its `from` body at value q.
  function jointDisplacement(joint, q) {
    if (joint.kind === 'P') {
      return { r: IDENTITY.r, t: joint.axis.map((a) => a * q) };
    }
    const r = rotation(joint.axis, q);
    const rp = apply(r, joint.point);
    return { r: r, t: [joint.point[0] - rp[0], joint.point[1] - rp[1], joint.point[2] - rp[2]] };
  }
  // Every body's displacement from its reference pose.
  function poses(q) {
    const out = scene.bodies.map(() => IDENTITY);
    for (const step of scene.tree) {
      const joint = scene.joints[step.joint];
      out[step.body] = compose(out[step.parent], jointDisplacement(joint, step.sign * q[step.joint]));
    }
    return out;
  }
  // Every joint's current site (a revolute's axis point; a slider between its leg's revolutes)
  // and axis.
  function sites(g) {
    const out = scene.joints.map((j) => {
      const pose = g[j.from];
      const p = apply(pose.r, j.point);
      return { point: [p[0] + pose.t[0], p[1] + pose.t[1], p[2] + pose.t[2]], axis: apply(pose.r, j.axis) };
    });
    scene.joints.forEach((j, k) => {
      const b = j.between;
      if (!b) return;
      const before = b.before !== null && b.before !== undefined ? out[b.before].point : null;
      const after = b.after !== null && b.after !== undefined ? out[b.after].point : null;
      if (before && after) {
        out[k].point = before.map((v, i) => v + b.fraction * (after[i] - v));
      } else if (before || after) {
        out[k].point = (before || after).slice();
      }
    });
    return out;
  }
  function endEffector(g) {
    const pose = g[scene.end_effector];
    const o = apply(pose.r, scene.end_effector_origin);
    return {
      position: [o[0] + pose.t[0], o[1] + pose.t[1], o[2] + pose.t[2]],
      rotation: product(pose.r, scene.end_effector_rotation),
    };
  }

  // ---- Drawing.
  const canvasHolder = document.getElementById('kinsyn-canvas');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  canvasHolder.appendChild(renderer.domElement);
  const world = new THREE.Scene();
  world.background = new THREE.Color(0xf8f9fa);
  const camera = new THREE.PerspectiveCamera(40, 1, s * 1e-3, s * 1e3);
  camera.up.set(0, 0, 1);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  world.add(new THREE.HemisphereLight(0xffffff, 0x667788, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 0.7);
  sun.position.set(2, -3, 5);
  world.add(sun);

  const COLOURS = {
    passive: 0x4c6ef5, actuated: 0xf76707, link: 0x868e96, ground: 0x343a40,
    'end-effector': 0x2f9e44, body: 0x74c0fc,
  };
  const material = (colour, opacity) => new THREE.MeshStandardMaterial({
    color: colour, roughness: 0.55, metalness: 0.1,
    transparent: opacity < 1, opacity: opacity, side: THREE.DoubleSide,
  });
  const Y = new THREE.Vector3(0, 1, 0);
  function orient(mesh, at, axis) {
    mesh.position.set(at[0], at[1], at[2]);
    const a = new THREE.Vector3(axis[0], axis[1], axis[2]);
    if (a.lengthSq() > 0) mesh.quaternion.setFromUnitVectors(Y, a.normalize());
  }
  function bar(from, to, mesh) {
    const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
    const length = Math.hypot(d[0], d[1], d[2]);
    mesh.visible = length > 1e-9 * s;
    if (!mesh.visible) return;
    orient(mesh, [(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2], d);
    mesh.scale.set(1, length, 1);
  }

  // Joint symbols: a revolute a cylinder along its axis, a slider a box along its guide, a
  // spherical joint one ball; a U's two revolutes cross at its centre, a C is a box on a
  // cylinder.
  const drawnGroups = new Set();
  const symbols = scene.joints.map((j) => {
    const colour = j.actuated ? COLOURS.actuated : COLOURS.passive;
    if (j.group === 'S') {
      if (drawnGroups.has(j.group_id) && !j.actuated) return null;
      drawnGroups.add(j.group_id);
      return { mesh: new THREE.Mesh(new THREE.SphereGeometry(0.06 * s, 24, 16), material(colour, 1)), ball: true };
    }
    const geometry = j.kind === 'R'
      ? new THREE.CylinderGeometry(0.035 * s, 0.035 * s, 0.16 * s, 24)
      : new THREE.BoxGeometry(0.07 * s, 0.2 * s, 0.07 * s);
    return { mesh: new THREE.Mesh(geometry, material(colour, 1)), ball: false };
  });
  symbols.forEach((sym) => sym && world.add(sym.mesh));

  // Bodies: links as bars between their joints' sites (a slider's sleeve on its `from` body
  // thicker than its rod), named bodies as a translucent polygon through their sites.
  const unitBar = (radius) => new THREE.CylinderGeometry(radius, radius, 1, 16);
  const bodies = scene.bodies.map((body, b) => {
    const colour = COLOURS[body.role];
    if (body.role === 'link' || body.outline.length < 3) {
      const bars = [];
      for (let k = 0; k + 1 < body.outline.length; k++) {
        const ends = [body.outline[k], body.outline[k + 1]];
        const sleeve = ends.some((j) => scene.joints[j].kind === 'P' && scene.joints[j].from === b);
        const mesh = new THREE.Mesh(unitBar((sleeve ? 0.03 : 0.018) * s), material(colour, 1));
        world.add(mesh);
        bars.push({ ends: ends, mesh: mesh });
      }
      return { bars: bars };
    }
    const n = body.outline.length;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * (n + 1)), 3));
    const index = [];
    for (let k = 0; k < n; k++) index.push(n, k, (k + 1) % n);
    geometry.setIndex(index);
    const face = new THREE.Mesh(geometry, material(colour, body.role === 'ground' ? 0.35 : 0.55));
    const edgeGeometry = new THREE.BufferGeometry();
    edgeGeometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * n), 3));
    const edge = new THREE.LineLoop(edgeGeometry, new THREE.LineBasicMaterial({ color: colour }));
    world.add(face);
    world.add(edge);
    return { face: face, edge: edge };
  });
  const frameAxes = new THREE.AxesHelper(0.4 * s);
  world.add(frameAxes);
  world.add(new THREE.AxesHelper(0.25 * s));

  let current = null;
  function draw(q) {
    const g = poses(q);
    const at = sites(g);
    scene.joints.forEach((j, k) => {
      const sym = symbols[k];
      if (sym) orient(sym.mesh, at[k].point, at[k].axis);
    });
    scene.bodies.forEach((body, b) => {
      const d = bodies[b];
      if (d.bars) {
        d.bars.forEach((bb) => bar(at[bb.ends[0]].point, at[bb.ends[1]].point, bb.mesh));
        return;
      }
      const n = body.outline.length;
      const face = d.face.geometry.attributes.position;
      const edge = d.edge.geometry.attributes.position;
      const centre = [0, 0, 0];
      body.outline.forEach((j, k) => {
        const p = at[j].point;
        face.setXYZ(k, p[0], p[1], p[2]);
        edge.setXYZ(k, p[0], p[1], p[2]);
        for (let i = 0; i < 3; i++) centre[i] += p[i] / n;
      });
      face.setXYZ(n, centre[0], centre[1], centre[2]);
      face.needsUpdate = true;
      edge.needsUpdate = true;
      d.face.geometry.computeVertexNormals();
      d.face.geometry.computeBoundingSphere();
      d.edge.geometry.computeBoundingSphere();
    });
    const ee = endEffector(g);
    const r = ee.rotation;
    frameAxes.position.set(ee.position[0], ee.position[1], ee.position[2]);
    frameAxes.quaternion.setFromRotationMatrix(new THREE.Matrix4().set(
      r[0], r[1], r[2], 0, r[3], r[4], r[5], 0, r[6], r[7], r[8], 0, 0, 0, 0, 1));
    current = { sites: at, endEffector: ee };
    render();
  }

  function box(points) {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    points.forEach((p) => { for (let i = 0; i < 3; i++) { lo[i] = Math.min(lo[i], p[i]); hi[i] = Math.max(hi[i], p[i]); } });
    return { lo: lo, hi: hi };
  }
  // The camera looks at the start configuration from above and aside, far enough for the
  // whole mechanism to fit with a margin.
  function fit() {
    const b = box(sites(poses(data.start)).map((x) => x.point));
    const centre = b.lo.map((v, i) => (v + b.hi[i]) / 2);
    const radius = Math.max(0.5 * Math.hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]), 0.5 * s);
    const distance = 1.5 * radius / Math.sin((camera.fov * Math.PI / 180) / 2);
    const dir = new THREE.Vector3(1.0, -1.6, 0.9).normalize();
    camera.position.set(centre[0] + distance * dir.x, centre[1] + distance * dir.y, centre[2] + distance * dir.z);
    camera.near = distance / 100;
    camera.far = distance * 100;
    controls.target.set(centre[0], centre[1], centre[2]);
    camera.updateProjectionMatrix();
    controls.update();
    const grid = new THREE.GridHelper(8 * radius, 16, 0xadb5bd, 0xdee2e6);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(centre[0], centre[1], b.lo[2] - 0.05 * s);
    world.add(grid);
  }

  let shown = { source: 'start', index: 0, frame: 0 };
  function resize() {
    const w = canvasHolder.clientWidth || 800, h = canvasHolder.clientHeight || 600;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  function render() {
    renderer.render(world, camera);
    publish();
  }
  // The page's state for scripts and tests: what is shown, the end-effector's frame as this
  // page computed it, and whether the mechanism's bounding box is on screen.
  function publish() {
    if (!current) return;
    const b = box(current.sites.map((x) => x.point));
    let onScreen = true;
    for (let c = 0; c < 8; c++) {
      const v = new THREE.Vector3(c & 1 ? b.hi[0] : b.lo[0], c & 2 ? b.hi[1] : b.lo[1], c & 4 ? b.hi[2] : b.lo[2]).project(camera);
      onScreen = onScreen && Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1 && Math.abs(v.z) <= 1;
    }
    const state = {
      source: shown.source, index: shown.index, frame: shown.frame,
      end_effector_position: current.endEffector.position,
      end_effector_rotation: current.endEffector.rotation,
      bounding_box_on_screen: onScreen,
      errors: window.kinsynErrors || [],
    };
    window.kinsynState = state;
    document.getElementById('kinsyn-state').textContent = JSON.stringify(state);
  }

  // ---- Controls: a slider per input, the modes, the assemblies.
  const readout = document.getElementById('kinsyn-shown');
  let timer = null;
  function stop() {
    if (timer !== null) { clearInterval(timer); timer = null; }
  }
  function show(source, index, frame) {
    let q = data.start, text = 'start configuration';
    if (source === 'sweep') {
      const sw = data.sweeps[index];
      q = sw.joint_values[frame];
      text = sw.input + ' = ' + format(sw.values[frame]) + ' ' + sw.unit + ' (other inputs held)';
    } else if (source === 'mode') {
      const m = data.modes[index];
      q = m.joint_values[frame];
      text = m.pattern + ' with ' + (m.locks === '-' ? 'no input' : m.locks) + ' locked: step ' + (frame - m.start);
    } else if (source === 'assembly') {
      q = data.assemblies[index].joint_values;
      text = data.assemblies[index].label;
    }
    shown = { source: source, index: index, frame: frame };
    readout.textContent = text;
    draw(q);
  }
  function format(v) { return Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(3) : v.toFixed(3); }

  const sliders = [];
  data.sweeps.forEach((sw, k) => {
    const row = document.createElement('div');
    row.className = 'row';
    const label = document.createElement('label');
    const input = document.createElement('input');
    input.type = 'range'; input.min = 0; input.max = sw.joint_values.length - 1; input.step = 1;
    input.value = sw.start;
    input.setAttribute('aria-label', sw.input);
    const value = document.createElement('span');
    value.className = 'value';
    value.textContent = format(sw.values[sw.start]) + ' ' + sw.unit;
    input.addEventListener('input', () => {
      stop();
      sliders.forEach((other, o) => { if (o !== k) { other.input.value = data.sweeps[o].start; other.value.textContent = format(data.sweeps[o].values[data.sweeps[o].start]) + ' ' + data.sweeps[o].unit; } });
      const f = Number(input.value);
      value.textContent = format(sw.values[f]) + ' ' + sw.unit;
      show('sweep', k, f);
    });
    label.textContent = sw.input;
    row.append(label, input, value);
    if (sw.stops.length) {
      // The range reached, in words; why each side stopped in the tooltip.
      const note = document.createElement('div');
      note.className = 'note';
      const last = sw.values.length - 1;
      note.textContent = 'reached ' + format(sw.values[0]) + ' to ' + format(sw.values[last]) + ' ' + sw.unit +
        ': the continuation stops ' + sw.stops.map((st) => (st.side < 0 ? 'below' : 'above')).join(' and ');
      note.title = sw.stops.map((st) => (st.side < 0 ? 'below: ' : 'above: ') + st.reason).join('\n');
      row.append(note);
    }
    document.getElementById('kinsyn-sliders').append(row);
    sliders.push({ input: input, value: value });
  });

  function animate(k) {
    stop();
    const m = data.modes[k];
    const n = m.joint_values.length;
    if (n <= 1) { show('mode', k, 0); return; }
    let f = m.start, dir = 1;
    timer = setInterval(() => {
      if (f + dir < 0 || f + dir >= n) dir = -dir;
      f += dir;
      show('mode', k, f);
    }, 50);
    show('mode', k, f);
  }
  data.modes.forEach((m, k) => {
    const button = document.createElement('button');
    button.textContent = m.pattern + ' (' + m.dof + ' dof) — locked: ' + (m.locks === '-' ? 'none' : m.locks);
    button.title = (m.group ? 'a displacement group' : 'not a group') + (m.parameters ? ': ' + m.parameters : '') +
      (m.joint_values.length <= 1 ? '; rigid at the start' : '') +
      (m.stops.length ? '; the walk stops ' + m.stops.map((st) => (st.side < 0 ? 'back' : 'ahead') + ': ' + st.reason).join('; ') : '');
    button.addEventListener('click', () => animate(k));
    document.getElementById('kinsyn-modes').append(button);
  });
  data.assemblies.forEach((a, k) => {
    const button = document.createElement('button');
    button.textContent = a.label + (a.continued_from_reference ? ' (continued from the reference)' : '') + (a.certified ? ', certified' : '');
    button.addEventListener('click', () => { stop(); show('assembly', k, 0); });
    document.getElementById('kinsyn-assemblies').append(button);
  });
  document.getElementById('kinsyn-stop').addEventListener('click', stop);
  document.getElementById('kinsyn-reset').addEventListener('click', () => { stop(); show('start', 0, 0); });
  window.addEventListener('resize', resize);
  controls.addEventListener('change', render);

  // The address may choose what is shown: #mode=K&frame=F, #sweep=K&frame=F, #assembly=K
  // (K from 0), #play=K animates mode K; #check=mode:K:F,sweep:K:F,assembly:K shows each in
  // turn and keeps each state, in order, in the element `kinsyn-checks` (for tests).
  function fromAddress() {
    const p = new URLSearchParams(window.location.hash.slice(1));
    if (p.has('check')) {
      const states = p.get('check').split(',').map((item) => {
        const [source, k, f] = item.split(':');
        show(source, Number(k), Number(f || 0));
        return window.kinsynState;
      });
      document.getElementById('kinsyn-checks').textContent = JSON.stringify(states);
      return;
    }
    const k = Number(p.get('mode') ?? p.get('sweep') ?? p.get('assembly') ?? p.get('play') ?? 0);
    const f = Number(p.get('frame') ?? 0);
    if (p.has('play') && data.modes[k]) animate(k);
    else if (p.has('mode') && data.modes[k]) show('mode', k, Math.min(f, data.modes[k].joint_values.length - 1));
    else if (p.has('sweep') && data.sweeps[k]) show('sweep', k, Math.min(f, data.sweeps[k].joint_values.length - 1));
    else if (p.has('assembly') && data.assemblies[k]) show('assembly', k, 0);
    else show('start', 0, 0);
  }
  window.addEventListener('hashchange', fromAddress);
  fit();
  resize();
  fromAddress();
}());
