// The interactive parts of `ncbridge convert --html`'s page (inlined into it at build time, after
// three.js): the top view zooms and pans; workingsteps are toggled and highlighted in both
// views; a feature's table row highlights its outline; the 3D view shows the stock, the
// toolpaths and the features, with a lowest-Z cut. When done it sets body[data-view3d] to the
// number of lines drawn (the browser test reads it), or to "unavailable: why".
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('ncb-data').textContent);

  // Top view: wheel zoom about the pointer, drag to pan, double click for the whole drawing.
  var svg = document.getElementById('top');
  var whole = svg.getAttribute('viewBox').split(' ').map(Number);
  var box = whole.slice();
  function setBox() { svg.setAttribute('viewBox', box.join(' ')); }
  function toSvg(event) {
    var r = svg.getBoundingClientRect();
    return [box[0] + (event.clientX - r.left) / r.width * box[2], box[1] + (event.clientY - r.top) / r.height * box[3]];
  }
  svg.addEventListener('wheel', function (event) {
    event.preventDefault();
    var p = toSvg(event);
    var k = event.deltaY < 0 ? 0.8 : 1.25;
    box = [p[0] - (p[0] - box[0]) * k, p[1] - (p[1] - box[1]) * k, box[2] * k, box[3] * k];
    setBox();
  }, {passive: false});
  var drag = null;
  svg.addEventListener('mousedown', function (event) { drag = toSvg(event); });
  window.addEventListener('mouseup', function () { drag = null; });
  svg.addEventListener('mousemove', function (event) {
    if (!drag) return;
    var p = toSvg(event);
    box[0] -= p[0] - drag[0];
    box[1] -= p[1] - drag[1];
    setBox();
  });
  svg.addEventListener('dblclick', function () { box = whole.slice(); setBox(); });

  // Workingstep toggles and highlighting (both views), feature rows.
  var wsVisible = {};
  var highlighted = null;
  var groups = [];
  var render = function () {};
  function applyWorkingsteps() {
    Array.prototype.forEach.call(svg.querySelectorAll('polyline[class^="ws"]'), function (line) {
      var ws = Number(line.getAttribute('class').replace(/^ws(\d+).*/, '$1'));
      line.style.display = wsVisible[ws] === false ? 'none' : '';
      line.classList.toggle('dim', highlighted !== null && highlighted !== ws);
    });
    groups.forEach(function (g, ws) {
      g.visible = wsVisible[ws] !== false;
      g.children.forEach(function (line) {
        line.material.opacity = highlighted === null || highlighted === ws ? 1 : 0.12;
        line.material.transparent = highlighted !== null && highlighted !== ws;
      });
    });
    render();
  }
  Array.prototype.forEach.call(document.querySelectorAll('input[data-ws]'), function (box) {
    box.addEventListener('change', function () { wsVisible[Number(box.dataset.ws)] = box.checked; applyWorkingsteps(); });
  });
  Array.prototype.forEach.call(document.querySelectorAll('li[data-ws]'), function (item) {
    var ws = Number(item.dataset.ws);
    item.addEventListener('mouseenter', function () { highlighted = ws; applyWorkingsteps(); });
    item.addEventListener('mouseleave', function () { highlighted = null; applyWorkingsteps(); });
  });
  var featureObjects = {};
  Array.prototype.forEach.call(document.querySelectorAll('tr[data-f]'), function (row) {
    row.addEventListener('click', function () {
      var on = !row.classList.contains('hl');
      Array.prototype.forEach.call(document.querySelectorAll('tr.hl'), function (r) { r.classList.remove('hl'); });
      Array.prototype.forEach.call(svg.querySelectorAll('g.hl'), function (g) { g.classList.remove('hl'); });
      Object.keys(featureObjects).forEach(function (k) { featureObjects[k].material.color.set(featureObjects[k].userData.colour); });
      if (on) {
        row.classList.add('hl');
        var outline = document.getElementById('f' + row.dataset.f);
        if (outline) outline.classList.add('hl');
        var object = featureObjects[row.dataset.f];
        if (object) object.material.color.set('#ffb000');
      }
      render();
    });
  });

  // 3D view.
  var host = document.getElementById('view3d');
  var status = document.getElementById('view3d-status');
  var renderer;
  try {
    if (typeof THREE === 'undefined') throw new Error('three.js is missing');
    renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  } catch (e) {
    status.textContent = '3D view unavailable: ' + e.message;
    document.body.dataset.view3d = 'unavailable: ' + e.message;
    return;
  }
  var width = host.clientWidth || 800, height = host.clientHeight || 520;
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  renderer.setClearColor(0xffffff);
  host.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  var s = data.stock;
  var centre = new THREE.Vector3((s.min[0] + s.max[0]) / 2, (s.min[1] + s.max[1]) / 2, (s.min[2] + s.max[2]) / 2);
  var size = Math.max(s.max[0] - s.min[0], s.max[1] - s.min[1], s.max[2] - s.min[2], 1);
  var camera = new THREE.PerspectiveCamera(35, width / height, size / 1000, size * 100);
  camera.up.set(0, 0, 1);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.screenSpacePanning = true;
  render = function () { renderer.render(scene, camera); };
  controls.addEventListener('change', render);
  window.addEventListener('resize', function () {
    var w = host.clientWidth || width, h = host.clientHeight || height;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  });
  function look(view) {
    var d = size * 1.7;
    var offsets = {iso: [0.8, -1.1, 0.9], top: [0, -0.0001, 1], front: [0, -1, 0.0001], side: [1, 0, 0.0001]};
    var o = offsets[view];
    camera.position.set(centre.x + o[0] * d, centre.y + o[1] * d, centre.z + o[2] * d);
    controls.target.copy(centre);
    controls.update();
    render();
  }

  scene.add(new THREE.Box3Helper(new THREE.Box3(new THREE.Vector3(s.min[0], s.min[1], s.min[2]),
                                                new THREE.Vector3(s.max[0], s.max[1], s.max[2])), 0x999999));
  scene.add(new THREE.AxesHelper(Math.max(size * 0.2, 10)));
  var cells = Math.ceil(size * 1.4 / 10);
  var grid = new THREE.GridHelper(cells * 10, cells, 0xdddddd, 0xeeeeee);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(centre.x, centre.y, s.min[2]);
  scene.add(grid);

  var lines = 0;
  var cutLines = [];
  data.paths.forEach(function (path) {
    while (groups.length <= path.w) {
      var g = new THREE.Group();
      groups.push(g);
      scene.add(g);
    }
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(path.p, 3));
    var material = path.r
        ? new THREE.LineDashedMaterial({color: 0xaaaaaa, dashSize: size / 150, gapSize: size / 150})
        : new THREE.LineBasicMaterial({color: data.colours[path.w % data.colours.length]});
    material.depthTest = false;  // toolpaths over the features' wireframes (a drill inside its hole)
    var line = new THREE.Line(geometry, material);
    line.renderOrder = 1;
    if (path.r) line.computeLineDistances();
    var low = Infinity;
    for (var i = 2; i < path.p.length; i += 3) low = Math.min(low, path.p[i]);
    line.userData = {low: low, rapid: !!path.r};
    groups[path.w].add(line);
    cutLines.push(line);
    lines += 1;
  });

  var features = new THREE.Group();
  scene.add(features);
  data.features.forEach(function (f) {
    var ring = [];
    if (f.k === 'c') {
      for (var a = 0; a <= 48; ++a) ring.push([f.x + f.d / 2 * Math.cos(a / 48 * 2 * Math.PI), f.y + f.d / 2 * Math.sin(a / 48 * 2 * Math.PI)]);
    } else if (f.k === 'r') {
      var cx = f.cx !== undefined ? f.cx : f.x, cy = f.cy !== undefined ? f.cy : f.y;
      var c = Math.cos(f.a * Math.PI / 180), n = Math.sin(f.a * Math.PI / 180);
      [[-1, -1], [1, -1], [1, 1], [-1, 1], [-1, -1]].forEach(function (q) {
        var u = q[0] * f.l / 2, v = q[1] * f.w / 2;
        ring.push([cx + u * c - v * n, cy + u * n + v * c]);
      });
    } else {
      for (var k = 0; k + 1 < f.ring.length; k += 2) ring.push([f.ring[k], f.ring[k + 1]]);
      ring.push(ring[0]);
    }
    var points = [];
    ring.forEach(function (q, j) {
      if (j === 0) return;
      var p = ring[j - 1];
      points.push(p[0], p[1], f.t, q[0], q[1], f.t, p[0], p[1], f.b, q[0], q[1], f.b);
    });
    var step = Math.max(1, Math.floor(ring.length / 8));
    for (var j = 0; j < ring.length - 1; j += step) points.push(ring[j][0], ring[j][1], f.t, ring[j][0], ring[j][1], f.b);
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    var object = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({color: f.col}));
    object.userData = {colour: f.col};
    featureObjects[String(f.i)] = object;
    features.add(object);
    lines += 1;
  });

  document.getElementById('show-rapids').addEventListener('change', function (event) {
    cutLines.forEach(function (line) { if (line.userData.rapid) line.material.visible = event.target.checked; });
    render();
  });
  document.getElementById('show-features').addEventListener('change', function (event) {
    features.visible = event.target.checked;
    render();
  });
  var zcut = document.getElementById('zcut');
  zcut.addEventListener('input', function () {
    var z = Number(zcut.value);
    var all = z <= Number(zcut.min);
    document.getElementById('zcut-value').textContent = all ? 'all' : 'Z ' + z.toFixed(2) + ' mm';
    cutLines.forEach(function (line) { line.visible = all || line.userData.low >= z; });
    render();
  });
  Array.prototype.forEach.call(document.querySelectorAll('button[data-view]'), function (button) {
    button.addEventListener('click', function () { look(button.dataset.view); });
  });
  look('iso');
  document.body.dataset.view3d = String(lines);

  // What the 3D view drew, read back from its canvas: pixels near each colour used (the browser
  // test checks that every workingstep and feature kind is on the screen).
  var used = {};
  data.paths.forEach(function (p) { if (!p.r) used[data.colours[p.w % data.colours.length]] = 0; });
  data.features.forEach(function (f) { used[f.col] = 0; });
  var gl = renderer.getContext();
  var w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  var pixels = new Uint8Array(w * h * 4);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  var wanted = Object.keys(used).map(function (c) {
    return [c, parseInt(c.substr(1, 2), 16), parseInt(c.substr(3, 2), 16), parseInt(c.substr(5, 2), 16)];
  });
  for (var i = 0; i < pixels.length; i += 4) {
    for (var k = 0; k < wanted.length; ++k) {
      var c = wanted[k];
      if (Math.abs(pixels[i] - c[1]) + Math.abs(pixels[i + 1] - c[2]) + Math.abs(pixels[i + 2] - c[3]) < 24) used[c[0]] += 1;
    }
  }
  document.body.dataset.view3dColours = JSON.stringify(used);
})();
