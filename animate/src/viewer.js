// precess-animate's viewer: a binary glTF (embedded as base64 in GLB_BASE64) played with
// WebGL 2. It reads what precess-animate writes: float positions without indices (triangles
// and line strips), one material colour per primitive, nodes with translation/rotation/
// children, and one animation of linear translation and rotation channels. Flat shading
// takes each face's normal from the screen-space derivatives of its position.
// Query: ?t=<s of playback> pauses there; yaw, pitch (degrees), dist, tx, ty, tz (space
// axes, z up) set the camera; probe=x,y;x,y writes those pixels' RGBA into #probe.
"use strict";
(function () {
  const query = new URLSearchParams(location.search);
  const num = (k, d) => (query.has(k) && isFinite(parseFloat(query.get(k))) ? parseFloat(query.get(k)) : d);
  const probeOut = document.getElementById("probe");

  // The .glb: header (12 bytes), JSON chunk, BIN chunk.
  const raw = atob(GLB_BASE64);
  const bytes = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
  const dv = new DataView(bytes.buffer);
  const jsonLen = dv.getUint32(12, true);
  const gltf = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLen)));
  const binAt = 20 + jsonLen + 8;
  const width = { SCALAR: 1, VEC3: 3, VEC4: 4 };
  function accessor(i) {
    const a = gltf.accessors[i];
    const v = gltf.bufferViews[a.bufferView];
    const at = binAt + (v.byteOffset || 0) + (a.byteOffset || 0);
    return new Float32Array(bytes.buffer.slice(at, at + 4 * a.count * width[a.type]));
  }

  const canvas = document.getElementById("view");
  const gl = canvas.getContext("webgl2", { preserveDrawingBuffer: true, antialias: false });
  if (!gl) {
    probeOut.textContent = "no webgl2";
    document.getElementById("time").textContent = "this browser has no WebGL 2";
    return;
  }

  // Shaders: position through model, view and projection; colour × (ambient + diffuse).
  function shader(kind, src) {
    const s = gl.createShader(kind);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  const program = gl.createProgram();
  gl.attachShader(program, shader(gl.VERTEX_SHADER, `#version 300 es
    in vec3 position; uniform mat4 model, viewProj; out vec3 world;
    void main() { vec4 w = model * vec4(position, 1.0); world = w.xyz; gl_Position = viewProj * w; }`));
  gl.attachShader(program, shader(gl.FRAGMENT_SHADER, `#version 300 es
    precision highp float; in vec3 world; uniform vec3 colour; uniform float lit; out vec4 outColour;
    void main() {
      vec3 n = normalize(cross(dFdx(world), dFdy(world)));
      float diffuse = abs(dot(n, normalize(vec3(0.3, 1.0, 0.5))));
      outColour = vec4(colour * mix(1.0, 0.35 + 0.65 * diffuse, lit), 1.0);
    }`));
  gl.linkProgram(program);
  gl.useProgram(program);
  const loc = (n) => gl.getUniformLocation(program, n);
  const uModel = loc("model"), uViewProj = loc("viewProj"), uColour = loc("colour"), uLit = loc("lit");
  const aPosition = gl.getAttribLocation(program, "position");

  // Meshes: one vertex array per primitive.
  const meshes = (gltf.meshes || []).map((m) =>
    m.primitives.map((p) => {
      const positions = accessor(p.attributes.POSITION);
      const vao = gl.createVertexArray();
      gl.bindVertexArray(vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
      gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
      gl.enableVertexAttribArray(aPosition);
      gl.vertexAttribPointer(aPosition, 3, gl.FLOAT, false, 0, 0);
      const mat = gltf.materials[p.material];
      const c = mat.pbrMetallicRoughness.baseColorFactor;
      const mode = p.mode === undefined ? 4 : p.mode;
      return { vao, count: positions.length / 3, mode, colour: [c[0], c[1], c[2]] };
    })
  );

  // 4×4 matrices, column-major.
  function mul(a, b) {
    const o = new Float32Array(16);
    for (let c = 0; c < 4; c++)
      for (let r = 0; r < 4; r++) {
        let s = 0;
        for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
        o[c * 4 + r] = s;
      }
    return o;
  }
  function trs(t, q) {
    const [x, y, z, w] = q;
    return new Float32Array([
      1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
      2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
      2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
      t[0], t[1], t[2], 1,
    ]);
  }
  function perspective(fovy, aspect, near, far) {
    const f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
    return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0]);
  }
  function lookAt(eye, target) {
    const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    const norm = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return [a[0] / l, a[1] / l, a[2] / l]; };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const f = norm(sub(target, eye)), s = norm(cross(f, [0, 1, 0])), u = cross(s, f);
    return new Float32Array([s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1]);
  }

  // The animation: per node, the sampled translation and rotation at playback time t.
  const channels = [];
  for (const anim of gltf.animations || [])
    for (const ch of anim.channels) {
      const s = anim.samplers[ch.sampler];
      channels.push({ node: ch.target.node, path: ch.target.path, times: accessor(s.input), values: accessor(s.output) });
    }
  const duration = channels.reduce((d, c) => Math.max(d, c.times[c.times.length - 1]), 0);
  function sample(ch, t) {
    const ts = ch.times, n = ch.path === "rotation" ? 4 : 3;
    let lo = 0, hi = ts.length - 1;
    if (t <= ts[0]) hi = 0;
    else if (t >= ts[hi]) lo = hi;
    else while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (ts[mid] <= t) lo = mid; else hi = mid; }
    const a = Array.from(ch.values.subarray(lo * n, lo * n + n));
    if (hi === lo) return a;
    const b = Array.from(ch.values.subarray(hi * n, hi * n + n));
    const u = (t - ts[lo]) / (ts[hi] - ts[lo]);
    if (n === 3) return a.map((v, k) => v + u * (b[k] - v));
    // Spherical-linear interpolation on the short arc.
    let d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    if (d < 0) { d = -d; for (let k = 0; k < 4; k++) b[k] = -b[k]; }
    let wa = 1 - u, wb = u;
    if (d < 0.9995) { const th = Math.acos(d), s = Math.sin(th); wa = Math.sin((1 - u) * th) / s; wb = Math.sin(u * th) / s; }
    const q = a.map((v, k) => wa * v + wb * b[k]);
    const l = Math.hypot(q[0], q[1], q[2], q[3]);
    return q.map((v) => v / l);
  }

  // Camera: orbiting a target (glTF axes: y up) at yaw, pitch and distance.
  const cam = {
    yaw: num("yaw", CAMERA.yaw), pitch: num("pitch", CAMERA.pitch), dist: num("dist", CAMERA.distance),
    target: [num("tx", CAMERA.target[0]), num("tz", CAMERA.target[2]), -num("ty", CAMERA.target[1])],
  };
  function viewProj() {
    const y = (cam.yaw * Math.PI) / 180, p = (cam.pitch * Math.PI) / 180;
    const eye = [cam.target[0] + cam.dist * Math.cos(p) * Math.sin(y), cam.target[1] + cam.dist * Math.sin(p), cam.target[2] + cam.dist * Math.cos(p) * Math.cos(y)];
    return mul(perspective((CAMERA.fovy * Math.PI) / 180, canvas.width / canvas.height, cam.dist / 100, cam.dist * 100), lookAt(eye, cam.target));
  }

  function draw(t) {
    const pose = {};
    for (const ch of channels) (pose[ch.node] = pose[ch.node] || {})[ch.path] = sample(ch, t);
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.uniformMatrix4fv(uViewProj, false, viewProj());
    const visit = (i, parent) => {
      const node = gltf.nodes[i], p = pose[i] || {};
      const m = mul(parent, trs(p.translation || node.translation || [0, 0, 0], p.rotation || node.rotation || [0, 0, 0, 1]));
      if (node.mesh !== undefined)
        for (const prim of meshes[node.mesh]) {
          gl.uniformMatrix4fv(uModel, false, m);
          gl.uniform3fv(uColour, prim.colour);
          gl.uniform1f(uLit, prim.mode === 4 ? 1 : 0);
          gl.bindVertexArray(prim.vao);
          gl.drawArrays(prim.mode, 0, prim.count);
        }
      for (const c of node.children || []) visit(c, m);
    };
    const identity = trs([0, 0, 0], [0, 0, 0, 1]);
    for (const i of gltf.scenes[gltf.scene || 0].nodes) visit(i, identity);
  }

  // Controls: play/pause, the slider, dragging to orbit, the wheel to zoom.
  const slider = document.getElementById("slider"), button = document.getElementById("play"), label = document.getElementById("time");
  slider.max = duration;
  let t = Math.min(Math.max(num("t", 0), 0), duration), playing = !query.has("t"), last = null;
  function show() {
    slider.value = t;
    label.textContent = `playback ${t.toFixed(3)} s of ${duration.toFixed(3)} s · simulated t = ${(START + t / TIME_SCALE).toFixed(4)} s`;
    button.textContent = playing ? "pause" : "play";
    draw(t);
  }
  button.onclick = () => { playing = !playing; last = null; if (playing && t >= duration) t = 0; show(); };
  slider.oninput = () => { t = parseFloat(slider.value); playing = false; show(); };
  let drag = null;
  canvas.onpointerdown = (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); };
  canvas.onpointerup = () => { drag = null; };
  canvas.onpointermove = (e) => {
    if (!drag) return;
    cam.yaw -= 0.4 * (e.clientX - drag[0]);
    cam.pitch = Math.max(-89, Math.min(89, cam.pitch + 0.4 * (e.clientY - drag[1])));
    drag = [e.clientX, e.clientY];
    if (!playing) show();
  };
  canvas.onwheel = (e) => { e.preventDefault(); cam.dist *= Math.exp(0.001 * e.deltaY); if (!playing) show(); };
  function frame(now) {
    if (playing) {
      if (last !== null) t += (now - last) / 1000;
      if (t >= duration) { t = duration; playing = false; }
      last = now;
      show();
    }
    requestAnimationFrame(frame);
  }
  show();
  requestAnimationFrame(frame);

  // Pixels for tests: canvas pixels from the top-left corner.
  if (query.has("probe")) {
    const out = [];
    for (const xy of query.get("probe").split(";")) {
      const [x, y] = xy.split(",").map(Number);
      const px = new Uint8Array(4);
      gl.readPixels(x, canvas.height - 1 - y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
      out.push(`${x},${y}:${px[0]},${px[1]},${px[2]}`);
    }
    probeOut.textContent = out.join(";");
  }
})();
