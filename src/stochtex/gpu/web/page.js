// stochtex web: renders the program of data.js (window.STOCHTEX_DATA,
// written by `stochtex web`) with WebGL 2. The fragment shader is the one
// render --gpu compiles (recipe "graph-web", GLSL ES 3.00); this file uploads the
// data, fills the parameter block and the camera's uniforms as the C++ host
// does (gpu/uploads.cpp setCameraUniforms), and turns mouse and touch input
// into the view's scale and offset. Nothing is fetched: the data is in
// data.js, its PNGs decoded here (DecompressionStream inflates them), so the
// page works from file:// and from any server.
'use strict';

(function () {
  const data = window.STOCHTEX_DATA;
  const canvas = document.getElementById('view');
  const statusBox = document.getElementById('status');

  function showError(message) {
    statusBox.textContent = message;
    statusBox.dataset.state = 'error';
  }
  if (!data) {
    showError('data.js is missing: open the folder stochtex web wrote');
    return;
  }
  const gl = canvas.getContext('webgl2', { antialias: false, alpha: false, preserveDrawingBuffer: true });
  if (!gl) {
    showError('this browser has no WebGL 2');
    return;
  }

  // ---- the state, read from and written to the address's fragment ----
  const state = {
    view: data.start.view,
    width: data.start.size[0],
    height: data.start.size[1],
    scale: data.start.scale,
    x: data.start.x,
    y: data.start.y,
    tilt: data.start.tilt,
    filter: data.start.filter,
    aniso: data.start.aniso,
    // The objects' orbit camera (scene's look-at camera, gpu/scene.cpp), from its default eye.
    mapping: 'uv',
    tiling: data.sceneCamera.tiling,
    yaw: 0,
    pitch: 0,
    distance: 1,
  };
  const objects = ['sphere', 'torus'];
  function orbitFromEye() {
    const [ex, ey, ez] = data.sceneCamera.eye, [tx, ty, tz] = data.sceneCamera.target;
    const d = [ex - tx, ey - ty, ez - tz];
    state.distance = Math.hypot(d[0], d[1], d[2]);
    state.pitch = Math.asin(d[1] / state.distance);
    state.yaw = Math.atan2(d[0], d[2]);
  }
  orbitFromEye();
  function readHash() {
    for (const part of location.hash.replace(/^#/, '').split('&')) {
      const [key, value] = part.split('=');
      if (value === undefined) continue;
      const number = Number(value);
      if (key === 'view' && ['zoom', 'plane'].concat(objects).includes(value)) state.view = value;
      else if (key === 'mapping' && (value === 'uv' || value === 'triplanar')) state.mapping = value;
      else if (key === 'tiling' && number > 0 && number <= 1e4) state.tiling = number;
      else if (key === 'yaw' && isFinite(number)) state.yaw = number;
      else if (key === 'pitch' && Math.abs(number) <= 1.5) state.pitch = number;
      else if (key === 'distance' && number >= 1.2 && number <= 50) state.distance = number;
      else if (key === 'filter' && ['none', 'paper', 'smooth'].includes(value)) state.filter = value;
      else if (key === 'size') {
        const [w, h] = value.split(',').map(Number);
        if (w >= 1 && h >= 1 && w <= 8192 && h <= 8192) { state.width = Math.round(w); state.height = Math.round(h); }
      } else if (key === 'scale' && number > 0 && isFinite(number)) state.scale = number;
      else if (key === 'x' && isFinite(number)) state.x = number;
      else if (key === 'y' && isFinite(number)) state.y = number;
      else if (key === 'tilt' && number >= 0 && number <= 89) state.tilt = number;
      else if (key === 'aniso' && number >= 1 && number <= 16) state.aniso = Math.round(number);
    }
  }
  function writeHash() {
    const hash = '#view=' + state.view + '&scale=' + state.scale.toPrecision(6) + '&x=' + state.x.toPrecision(8) +
      '&y=' + state.y.toPrecision(8) + '&filter=' + state.filter + '&aniso=' + state.aniso + '&tilt=' + state.tilt +
      '&size=' + state.width + ',' + state.height +
      (objects.includes(state.view) ? '&mapping=' + state.mapping + '&tiling=' + state.tiling + '&yaw=' +
        state.yaw.toPrecision(6) + '&pitch=' + state.pitch.toPrecision(6) + '&distance=' +
        state.distance.toPrecision(6) : '');
    history.replaceState(null, '', hash);
  }
  readHash();

  // ---- data: base64, PNG (8- and 16-bit, not interlaced), raw floats ----
  function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return bytes;
  }
  async function decodePng(bytes) {
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    let width = 0, height = 0, depth = 8, colourType = 0;
    const compressed = [];
    for (let at = 8; at + 8 <= bytes.length;) {
      const length = view.getUint32(at);
      const type = String.fromCharCode(bytes[at + 4], bytes[at + 5], bytes[at + 6], bytes[at + 7]);
      if (type === 'IHDR') {
        width = view.getUint32(at + 8);
        height = view.getUint32(at + 12);
        depth = bytes[at + 16];
        colourType = bytes[at + 17];
        if (bytes[at + 20] !== 0) throw new Error('interlaced PNG');
      } else if (type === 'IDAT') compressed.push(bytes.subarray(at + 8, at + 8 + length));
      else if (type === 'IEND') break;
      at += 12 + length;
    }
    const channels = { 0: 1, 2: 3, 4: 2, 6: 4 }[colourType];
    if (!channels || (depth !== 8 && depth !== 16)) throw new Error('PNG colour type ' + colourType + ', depth ' + depth);
    const stream = new Blob(compressed).stream().pipeThrough(new DecompressionStream('deflate'));
    const raw = new Uint8Array(await new Response(stream).arrayBuffer());
    const bpp = channels * depth / 8, stride = width * bpp;
    const out = new Uint8Array(height * stride);
    for (let y = 0; y < height; ++y) {
      const filter = raw[y * (stride + 1)];
      const src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
      const row = out.subarray(y * stride, (y + 1) * stride);
      const up = y > 0 ? out.subarray((y - 1) * stride, y * stride) : new Uint8Array(stride);
      for (let i = 0; i < stride; ++i) {
        const a = i >= bpp ? row[i - bpp] : 0, b = up[i], c = i >= bpp ? up[i - bpp] : 0;
        let predictor = 0;
        if (filter === 1) predictor = a;
        else if (filter === 2) predictor = b;
        else if (filter === 3) predictor = (a + b) >> 1;
        else if (filter === 4) {
          const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
          predictor = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }
        row[i] = (src[i] + predictor) & 255;
      }
    }
    if (depth === 8) return out;
    const values = new Float32Array(out.length / 2);  // 16-bit codes of [0, 1], big-endian
    for (let i = 0; i < values.length; ++i) values[i] = ((out[2 * i] << 8) | out[2 * i + 1]) / 65535;
    return values;
  }
  async function levelValues(level) {
    const bytes = bytesOf(level.data);
    if (level.encoding === 'f32') return new Float32Array(bytes.buffer);
    return decodePng(bytes);
  }

  // ---- program ----
  function compile(type, source) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error('shader: ' + gl.getShaderInfoLog(shader));
    return shader;
  }
  function link(vertex, fragment) {
    const p = gl.createProgram();
    gl.attachShader(p, compile(gl.VERTEX_SHADER, vertex));
    gl.attachShader(p, compile(gl.FRAGMENT_SHADER, fragment));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error('program: ' + gl.getProgramInfoLog(p));
    gl.uniformBlockBinding(p, gl.getUniformBlockIndex(p, 'PatternParameters'), 0);
    return p;
  }
  let program, sceneProgram;
  try {
    program = link(data.vertex, data.fragment);  // the zoom and plane views
    sceneProgram = link(data.sceneVertex, data.sceneFragment);  // the lit objects
  } catch (error) {
    showError(error.message);
    return;
  }
  const vao = gl.createVertexArray();
  let current = program;
  const uniform = (name) => gl.getUniformLocation(current, name);

  // ---- textures: each sampler on a unit of its own; a prefiltered table per filter ----
  const formats = {
    R32F: [gl.R32F, gl.RED, gl.FLOAT],
    RGBA8: [gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE],
    SRGB8: [gl.SRGB8, gl.RGB, gl.UNSIGNED_BYTE],
    RGB32F: [gl.RGB32F, gl.RGB, gl.FLOAT],
  };
  const units = new Map();  // sampler name → { unit, target, byFilter: { paper, smooth } or texture }
  async function upload(entry) {
    const [internal, format, type] = formats[entry.format];
    const texture = gl.createTexture();
    const target = entry.target === 'array' ? gl.TEXTURE_2D_ARRAY : gl.TEXTURE_2D;
    gl.bindTexture(target, texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    for (let l = 0; l < entry.levels.length; ++l) {
      const level = entry.levels[l];
      const values = await levelValues(level);
      gl.bindTexture(target, texture);
      if (target === gl.TEXTURE_2D_ARRAY)
        gl.texImage3D(target, l, internal, level.width, level.height / entry.layers, entry.layers, 0, format, type, values);
      else gl.texImage2D(target, l, internal, level.width, level.height, 0, format, type, values);
    }
    gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, entry.levels.length > 1 ? gl.NEAREST_MIPMAP_NEAREST : gl.NEAREST);
    gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texParameteri(target, gl.TEXTURE_MAX_LEVEL, entry.levels.length - 1);
    let slot = units.get(entry.uniform);
    if (!slot) {
      slot = { unit: units.size, target: target, textures: {} };
      units.set(entry.uniform, slot);
    }
    slot.textures[entry.filter || 'all'] = texture;
  }

  // ---- the objects' meshes (positions, normals, uv: 8 floats a vertex), made on first use ----
  const meshes = {};
  function mesh(name) {
    if (meshes[name]) return meshes[name];
    const source = data.meshes[name];
    const vertexArray = gl.createVertexArray();
    gl.bindVertexArray(vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, bytesOf(source.vertices), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, bytesOf(source.indices), gl.STATIC_DRAW);
    [[0, 3, 0], [1, 3, 3], [2, 2, 6]].forEach(([attribute, size, offset]) => {
      gl.enableVertexAttribArray(attribute);
      gl.vertexAttribPointer(attribute, size, gl.FLOAT, false, 32, offset * 4);
    });
    gl.bindVertexArray(null);
    return (meshes[name] = { vertexArray: vertexArray, count: source.count });
  }
  // scene's look-at camera and projection (gpu/scene.cpp SceneCamera), column-major.
  function viewProjection(eye, target, fovDeg, aspect) {
    const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    const normalize = (v) => { const l = Math.hypot(v[0], v[1], v[2]); return [v[0] / l, v[1] / l, v[2] / l]; };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const f = normalize(sub(target, eye)), s = normalize(cross(f, [0, 1, 0])), u = cross(s, f);
    const view = [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye),
      dot(f, eye), 1];
    const t = 1 / Math.tan(0.5 * fovDeg * Math.PI / 180), zn = 0.05, zf = 50;
    const proj = [t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, (zf + zn) / (zn - zf), -1, 0, 0, 2 * zf * zn / (zn - zf), 0];
    const out = new Float32Array(16);
    for (let c = 0; c < 4; ++c)
      for (let r = 0; r < 4; ++r) {
        let v = 0;
        for (let k = 0; k < 4; ++k) v += proj[k * 4 + r] * view[c * 4 + k];
        out[c * 4 + r] = v;
      }
    return out;
  }
  function eye() {
    const t = data.sceneCamera.target, c = Math.cos(state.pitch);
    return [t[0] + state.distance * c * Math.sin(state.yaw), t[1] + state.distance * Math.sin(state.pitch),
      t[2] + state.distance * c * Math.cos(state.yaw)];
  }

  // ---- the parameter block ----
  const parameters = gl.createBuffer();
  function fillBlock() {
    const bytes = bytesOf(data.blocks[state.filter]);
    new DataView(bytes.buffer).setInt32(data.anisoOffset, state.aniso, true);
    gl.bindBuffer(gl.UNIFORM_BUFFER, parameters);
    gl.bufferData(gl.UNIFORM_BUFFER, bytes, gl.DYNAMIC_DRAW);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, parameters);
  }

  // ---- drawing ----
  let drawn = 0, pending = false;
  function draw() {
    pending = false;
    const dpr = window.devicePixelRatio || 1;
    if (canvas.width !== state.width || canvas.height !== state.height) {
      canvas.width = state.width;
      canvas.height = state.height;
    }
    canvas.style.width = state.width / dpr + 'px';
    canvas.style.height = state.height / dpr + 'px';
    const object = objects.includes(state.view);
    current = object ? sceneProgram : program;
    gl.useProgram(current);
    for (const [name, slot] of units) {
      gl.activeTexture(gl.TEXTURE0 + slot.unit);
      gl.bindTexture(slot.target, slot.textures[state.filter] || slot.textures.paper || slot.textures.all);
      gl.uniform1i(uniform(name), slot.unit);
    }
    fillBlock();
    gl.viewport(0, 0, state.width, state.height);
    if (object) drawObject();
    else drawView();
    ++drawn;
    statusBox.textContent = state.view + ' view, ' +
      (object ? state.mapping + ' mapping, ' + state.tiling + ' periods across' : state.scale.toPrecision(4) +
        ' texels per pixel') + ', filter ' + state.filter + (state.filter === 'none' ? '' : ', K = ' + state.aniso) +
      (state.view === 'plane' ? ', tilt ' + state.tilt + '°' : '') + ' — frame ' + drawn;
    statusBox.dataset.state = 'ready';
    statusBox.dataset.frames = String(drawn);
  }
  // A lit object as `scene` draws it (gpu/scene_render.cpp): its light, its
  // slate background (sRGB codes: the canvas holds codes), the rasterizer's
  // footprints.
  function drawObject() {
    const m = mesh(state.view);
    gl.clearColor(0.08, 0.09, 0.11, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    const e = eye();
    gl.uniformMatrix4fv(uniform('uViewProjection'), false,
      viewProjection(e, data.sceneCamera.target, data.sceneCamera.fov, state.width / state.height));
    gl.uniform1f(uniform('uTiling'), state.tiling);
    gl.uniform1i(uniform('uFiltered'), state.filter === 'none' ? 0 : 1);
    gl.uniform1i(uniform('uShadesLight'), data.shadesLight ? 1 : 0);
    gl.uniform1i(uniform('uTriplanar'), state.mapping === 'triplanar' && !data.shadesLight ? 1 : 0);
    const light = [0.45, 0.8, 0.4], n = Math.hypot(light[0], light[1], light[2]);
    gl.uniform3f(uniform('uLight'), light[0] / n, light[1] / n, light[2] / n);
    gl.uniform3f(uniform('uEye'), e[0], e[1], e[2]);
    gl.uniform1i(uniform('uEncodeSrgb'), 1);
    gl.bindVertexArray(m.vertexArray);
    gl.drawElements(gl.TRIANGLES, m.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
    gl.disable(gl.DEPTH_TEST);
  }
  function drawView() {
    const tilt = state.tilt * Math.PI / 180;
    gl.uniform1i(uniform('uPlane'), state.view === 'plane' ? 1 : 0);
    gl.uniform1f(uniform('uTanHalfFov'), Math.tan(0.5 * data.start.fov * Math.PI / 180));
    gl.uniform1f(uniform('uSinTilt'), Math.sin(tilt));
    gl.uniform1f(uniform('uCosTilt'), Math.cos(tilt));
    gl.uniform2f(uniform('uViewSize'), state.width, state.height);
    gl.uniform2f(uniform('uOffset'), state.x, state.y);
    gl.uniform1f(uniform('uScale'), state.scale);
    gl.uniform3f(uniform('uSky'), data.sky[0], data.sky[1], data.sky[2]);
    gl.uniform1i(uniform('uFiltered'), state.filter === 'none' ? 0 : 1);
    gl.bindVertexArray(vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }
  function redraw() {
    syncControls();
    writeHash();
    if (!pending) {
      pending = true;
      requestAnimationFrame(draw);
    }
  }

  // ---- controls ----
  const controls = {
    camera: document.getElementById('camera'),
    filter: document.getElementById('filter'),
    aniso: document.getElementById('aniso'),
    tilt: document.getElementById('tilt'),
    mapping: document.getElementById('mapping'),
    tiling: document.getElementById('tiling'),
  };
  function syncControls() {
    controls.camera.value = state.view;
    controls.filter.value = state.filter;
    controls.aniso.value = String(state.aniso);
    controls.tilt.value = String(state.tilt);
    controls.tilt.disabled = state.view !== 'plane';
    controls.mapping.value = state.mapping;
    controls.mapping.disabled = !objects.includes(state.view) || data.shadesLight;
    controls.tiling.value = String(state.tiling);
    controls.tiling.disabled = !objects.includes(state.view);
    document.getElementById('tiltValue').textContent = String(state.tilt);
  }
  controls.camera.addEventListener('change', () => { state.view = controls.camera.value; redraw(); });
  controls.filter.addEventListener('change', () => { state.filter = controls.filter.value; redraw(); });
  controls.aniso.addEventListener('change', () => {
    const k = Math.round(Number(controls.aniso.value));
    if (k >= 1 && k <= 16) state.aniso = k;
    redraw();
  });
  controls.tilt.addEventListener('input', () => { state.tilt = Number(controls.tilt.value); redraw(); });
  controls.mapping.addEventListener('change', () => { state.mapping = controls.mapping.value; redraw(); });
  controls.tiling.addEventListener('change', () => {
    const t = Number(controls.tiling.value);
    if (t > 0 && t <= 1e4) state.tiling = t;
    redraw();
  });
  document.getElementById('reset').addEventListener('click', () => {
    Object.assign(state, { scale: data.start.scale, x: data.start.x, y: data.start.y, tilt: data.start.tilt,
      tiling: data.sceneCamera.tiling });
    orbitFromEye();
    redraw();
  });
  window.addEventListener('hashchange', () => { readHash(); redraw(); });

  // Zoom by `factor` keeping the texel under canvas pixel (px, py) in place
  // (the zoom view: texel = offset + p·scale); the plane keeps its centre.
  function zoomAbout(factor, px, py) {
    if (objects.includes(state.view)) {  // the orbit's distance
      state.distance = Math.min(Math.max(state.distance * factor, 1.2), 50);
      redraw();
      return;
    }
    const scale = Math.min(Math.max(state.scale * factor, 1 / 64), 4096);
    if (state.view === 'plane') { px = state.width / 2; py = state.height / 2; }
    state.x += px * (state.scale - scale);
    state.y += py * (state.scale - scale);
    state.scale = scale;
    redraw();
  }
  function canvasPoint(event) {
    const box = canvas.getBoundingClientRect();
    return [(event.clientX - box.left) * canvas.width / box.width, (event.clientY - box.top) * canvas.height / box.height];
  }
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const [px, py] = canvasPoint(event);
    const lines = event.deltaMode === 1 ? 33 : event.deltaMode === 2 ? 400 : 1;
    zoomAbout(Math.pow(2, event.deltaY * lines / 400), px, py);
  }, { passive: false });
  // Pointers (mouse, pen, fingers): one drags the view, two pinch.
  const pointers = new Map();
  canvas.addEventListener('pointerdown', (event) => {
    canvas.setPointerCapture(event.pointerId);
    pointers.set(event.pointerId, canvasPoint(event));
    canvas.classList.add('dragging');
  });
  canvas.addEventListener('pointermove', (event) => {
    if (!pointers.has(event.pointerId)) return;
    const before = [...pointers.values()];
    const point = canvasPoint(event);
    pointers.set(event.pointerId, point);
    if (pointers.size === 1) {
      const [x0, y0] = before[0];
      if (objects.includes(state.view)) {  // orbit about the object
        state.yaw -= (point[0] - x0) * 0.01;
        state.pitch = Math.min(Math.max(state.pitch + (point[1] - y0) * 0.01, -1.4), 1.4);
      } else {
        state.x -= (point[0] - x0) * state.scale;
        state.y -= (point[1] - y0) * state.scale;
      }
      redraw();
    } else if (pointers.size === 2) {
      const after = [...pointers.values()];
      const span = (p) => Math.hypot(p[0][0] - p[1][0], p[0][1] - p[1][1]);
      if (span(after) > 0 && span(before) > 0)
        zoomAbout(span(before) / span(after), (after[0][0] + after[1][0]) / 2, (after[0][1] + after[1][1]) / 2);
    }
  });
  const release = (event) => {
    pointers.delete(event.pointerId);
    if (pointers.size === 0) canvas.classList.remove('dragging');
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);

  // ---- what the page shows of the pattern ----
  document.getElementById('name').textContent = data.name;
  document.title = 'stochtex — ' + data.name;
  const rows = [
    ['example size', data.exampleSize + ' texels'],
    ['grid density', String(data.pattern.gridDensity)],
    ['leaves', data.pattern.leaves.join(', ')],
    ['operations', data.pattern.operations.map((op) => op.id + ' (' + op.type + ')').join(', ')],
    ['response', data.pattern.response],
    ['estimator', data.pattern.estimator],
  ];
  const table = document.getElementById('program');
  for (const [key, value] of rows) {
    const row = table.insertRow();
    row.insertCell().textContent = key;
    row.insertCell().textContent = value;
  }
  document.getElementById('source').textContent = data.pattern.source;

  window.stochtex = { state: state, redraw: redraw };
  Promise.all(data.textures.map(upload)).then(redraw, (error) => showError('data: ' + error.message));
})();
