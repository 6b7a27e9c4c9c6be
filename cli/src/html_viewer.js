// The interactive parts of the --html page (inlined into it at build time, after three.js). The
// top view zooms about the pointer and pans, shows the pointer's coordinates and a scale bar in
// mm. One state drives both views: workingsteps shown, feature kinds shown (a kind hides its
// outlines and the toolpaths that cut its features), rapid and cutting moves, outlines, labels,
// the lowest Z shown (or only that layer), the highlighted feature (a table row: the feature and
// the toolpaths of its workingsteps) or workingstep (hover). When done it sets body data
// attributes the browser test reads: view3d (lines drawn, or "unavailable: why"),
// view3dColours (pixels of each colour on the 3D canvas), drawn2d (SVG elements by kind), and
// with #selftest in the address, selftest (what a click on a feature row and a kind toggle did).
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('ncb-data').textContent);
  // #picture: the top view alone, filling the window; #picture3d: the 3D view alone (the
  // documentation's screenshots, scripts/make-doc-pictures.sh).
  if (location.hash === '#picture') document.body.classList.add('picture');
  if (location.hash === '#picture3d') document.body.classList.add('picture3d');
  function each(selector, f, root) { Array.prototype.forEach.call((root || document).querySelectorAll(selector), f); }

  // ---- Top view: wheel zoom about the pointer, drag to pan, double click for the whole drawing.
  var svg = document.getElementById('top');
  var whole = svg.getAttribute('viewBox').split(' ').map(Number);
  var box = whole.slice();
  var scale = Number(svg.dataset.scale), x0 = Number(svg.dataset.x0), y0 = Number(svg.dataset.y0), margin = Number(svg.dataset.margin);
  var scalebar = document.getElementById('scalebar');
  var pointer = document.getElementById('pointer');
  function updateScale() {
    var r = svg.getBoundingClientRect();
    var pxPerMm = r.width / box[2] * scale;
    if (!(pxPerMm > 0)) return;
    var target = 120 / pxPerMm, p = Math.pow(10, Math.floor(Math.log10(target))), mm = p;
    [1, 2, 5, 10].forEach(function (k) { if (k * p <= target) mm = k * p; });
    scalebar.firstChild.style.width = (mm * pxPerMm) + 'px';
    scalebar.lastChild.textContent = (mm >= 1 ? mm : mm.toPrecision(1)) + ' mm';
  }
  function setBox() { svg.setAttribute('viewBox', box.join(' ')); updateScale(); }
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
    var p = toSvg(event);
    pointer.textContent = 'X ' + (x0 + (p[0] - margin) / scale).toFixed(2) + '  Y ' + (y0 - (p[1] - margin) / scale).toFixed(2) + ' mm';
    if (!drag) return;
    box[0] -= p[0] - drag[0];
    box[1] -= p[1] - drag[1];
    setBox();
  });
  svg.addEventListener('mouseleave', function () { pointer.textContent = ''; });
  svg.addEventListener('dblclick', function () { box = whole.slice(); setBox(); });
  window.addEventListener('resize', updateScale);
  updateScale();

  // ---- The state both views show.
  var state = {ws: {}, kinds: {}, cuts: true, rapids: true, outlines: true, labels: true, zlow: -Infinity, band: false,
               feature: null, hoverWs: null};
  var render = function () {};
  var lines2d = [];
  each('#paths [data-low]', function (el) {
    lines2d.push({el: el, ws: el.dataset.ws === undefined ? -1 : Number(el.dataset.ws), low: Number(el.dataset.low),
                  rapid: el.classList.contains('rp')});
  });
  var lines3d = [];
  var features3d = {};
  function featureOf(ws) { return ws >= 0 && ws < data.wsf.length ? data.wsf[ws] : -1; }
  function kindShown(feature) { return feature < 0 || state.kinds[data.fk[feature]] !== false; }
  function zShown(low) {
    if (low < state.zlow) return false;
    return !state.band || low <= state.zlow + 0.05;
  }
  function shown(line) {
    if (line.rapid ? !state.rapids : !state.cuts) return false;
    if (line.ws >= 0 && (state.ws[line.ws] === false || !kindShown(featureOf(line.ws)))) return false;
    return zShown(line.low);
  }
  function lit(line) {
    if (state.feature !== null) return line.ws >= 0 && featureOf(line.ws) === state.feature;
    if (state.hoverWs !== null) return line.ws === state.hoverWs;
    return true;
  }
  function apply() {
    lines2d.forEach(function (line) {
      line.el.classList.toggle('off', !shown(line));
      line.el.classList.toggle('dim', !lit(line));
    });
    each('#outlines g.ol', function (g) {
      var i = Number(g.id.substr(1));
      g.classList.toggle('off', !state.outlines || !kindShown(i));
      g.classList.toggle('hl', state.feature === i);
      g.classList.toggle('dim', state.feature !== null && state.feature !== i);
    });
    each('#labels text', function (t) {
      var i = Number(t.dataset.f);
      t.classList.toggle('off', !state.labels || !state.outlines || !kindShown(i));
    });
    each('tr[data-f]', function (row) {
      row.classList.toggle('hl', state.feature === Number(row.dataset.f));
      row.style.opacity = kindShown(Number(row.dataset.f)) ? '' : '0.45';
    });
    each('li[data-ws]', function (item) {
      var ws = Number(item.dataset.ws);
      item.classList.toggle('hl', state.feature !== null && featureOf(ws) === state.feature);
    });
    lines3d.forEach(function (line) {
      line.visible = shown(line.userData);
      var on = lit(line.userData);
      line.material.transparent = !on;
      line.material.opacity = on ? 1 : 0.1;
    });
    Object.keys(features3d).forEach(function (k) {
      var object = features3d[k], i = Number(k);
      object.visible = state.outlines && kindShown(i);
      object.material.color.set(state.feature === i ? '#ffb000' : object.userData.colour);
    });
    render();
  }
  each('input[data-ws]', function (input) {
    input.addEventListener('change', function () { state.ws[Number(input.dataset.ws)] = input.checked; apply(); });
  });
  each('li[data-ws]', function (item) {
    var ws = Number(item.dataset.ws);
    item.addEventListener('mouseenter', function () { state.hoverWs = ws; apply(); });
    item.addEventListener('mouseleave', function () { state.hoverWs = null; apply(); });
  });
  each('input[data-kind]', function (input) {
    input.addEventListener('change', function () { state.kinds[Number(input.dataset.kind)] = input.checked; apply(); });
  });
  function selectFeature(i) {
    state.feature = state.feature === i ? null : i;
    apply();
  }
  each('tr[data-f]', function (row) { row.addEventListener('click', function () { selectFeature(Number(row.dataset.f)); }); });
  each('#outlines g.ol', function (g) { g.addEventListener('click', function () { selectFeature(Number(g.id.substr(1))); }); });
  [['show-cuts', 'cuts'], ['show-rapids', 'rapids'], ['show-features', 'outlines'], ['show-labels', 'labels'], ['zband', 'band']].forEach(function (p) {
    document.getElementById(p[0]).addEventListener('change', function (event) { state[p[1]] = event.target.checked; apply(); });
  });
  var zcut = document.getElementById('zcut');
  zcut.addEventListener('input', function () {
    var z = Number(zcut.value);
    var all = z <= Number(zcut.min);
    document.getElementById('zcut-value').textContent = all ? 'all' : 'Z ' + z.toFixed(2) + ' mm';
    state.zlow = all ? -Infinity : z;
    apply();
  });

  var counts = {cut: 0, rapid: 0, outlines: 0, labels: 0};
  lines2d.forEach(function (l) { if (l.el.tagName === 'polyline') counts[l.rapid ? 'rapid' : 'cut'] += 1; });
  counts.points = document.querySelectorAll('#paths circle').length;  // drilling cycles, from above
  counts.outlines = document.querySelectorAll('#outlines g.ol').length;
  counts.labels = document.querySelectorAll('#labels text').length;
  document.body.dataset.drawn2d = JSON.stringify(counts);

  // What a click on the first feature row with toolpaths and a kind toggle do (the browser test).
  function selftest() {
    var result = {};
    var row = null;
    each('tr[data-f]', function (r) { if (!row && data.wsf.indexOf(Number(r.dataset.f)) >= 0) row = r; });
    if (row) {
      row.click();
      var f = Number(row.dataset.f);
      var expected = lines2d.filter(function (l) { return l.ws >= 0 && featureOf(l.ws) === f; }).length;
      result.feature = f;
      result.lit = lines2d.filter(function (l) { return !l.el.classList.contains('dim'); }).length;
      result.expected = expected;
      result.outlineHighlighted = !!document.querySelector('#outlines g.hl') === !!document.getElementById('f' + f);
      result.rowHighlighted = row.classList.contains('hl');
      row.click();
      result.clearedDim = document.querySelectorAll('#paths .dim').length;
      var toggle = document.querySelector('input[data-kind="' + data.fk[f] + '"]');
      toggle.checked = false;
      toggle.dispatchEvent(new Event('change'));
      result.hiddenByKind = lines2d.filter(function (l) { return l.el.classList.contains('off'); }).length;
      result.kindLines = lines2d.filter(function (l) { return l.ws >= 0 && featureOf(l.ws) >= 0 && data.fk[featureOf(l.ws)] === data.fk[f]; }).length;
      toggle.checked = true;
      toggle.dispatchEvent(new Event('change'));
    }
    document.body.dataset.selftest = JSON.stringify(result);
  }

  // ---- 3D view.
  var host = document.getElementById('view3d');
  var status = document.getElementById('view3d-status');
  var renderer;
  try {
    if (typeof THREE === 'undefined') throw new Error('three.js is missing');
    renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  } catch (e) {
    status.textContent = '3D view unavailable: ' + e.message;
    document.body.dataset.view3d = 'unavailable: ' + e.message;
    if (location.hash === '#selftest') selftest();
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

  var drawn = 0;
  data.paths.forEach(function (path) {
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(path.p, 3));
    var material = path.r
        ? new THREE.LineDashedMaterial({color: 0x999999, dashSize: size / 150, gapSize: size / 150})
        : new THREE.LineBasicMaterial({color: data.colours[path.w % data.colours.length]});
    material.depthTest = false;  // toolpaths over the features' wireframes (a drill inside its hole)
    var line = new THREE.Line(geometry, material);
    line.renderOrder = 1;
    if (path.r) line.computeLineDistances();
    var low = Infinity;
    for (var i = 2; i < path.p.length; i += 3) low = Math.min(low, path.p[i]);
    line.userData = {low: low, rapid: !!path.r, ws: path.w};
    scene.add(line);
    lines3d.push(line);
    drawn += 1;
  });

  data.features.forEach(function (f) {
    var points = [];
    f.rings.forEach(function (flat) {
      var ring = [];
      for (var k = 0; k + 1 < flat.length; k += 2) ring.push([flat[k], flat[k + 1]]);
      ring.push(ring[0]);
      ring.forEach(function (q, j) {
        if (j === 0) return;
        var p = ring[j - 1];
        points.push(p[0], p[1], f.t, q[0], q[1], f.t, p[0], p[1], f.b, q[0], q[1], f.b);
      });
      var step = Math.max(1, Math.floor(ring.length / 8));
      for (var j = 0; j < ring.length - 1; j += step) points.push(ring[j][0], ring[j][1], f.t, ring[j][0], ring[j][1], f.b);
    });
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    var object = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({color: f.col}));
    object.userData = {colour: f.col};
    features3d[String(f.i)] = object;
    scene.add(object);
    drawn += 1;
  });

  Array.prototype.forEach.call(document.querySelectorAll('button[data-view]'), function (button) {
    button.addEventListener('click', function () { look(button.dataset.view); });
  });
  look('iso');
  document.body.dataset.view3d = String(drawn);

  // What the 3D view drew, read back from its canvas: pixels near each colour used (the browser
  // test checks that every workingstep and feature kind is on the screen).
  // Workingsteps seen from above as a point (a plunge, a drill) may lie under later ones: only
  // those whose cuts span some of the drawing in XY are counted.
  var used = {};
  var spans = {};
  data.paths.forEach(function (p) {
    if (p.r) return;
    var b = spans[p.w] || (spans[p.w] = [Infinity, Infinity, -Infinity, -Infinity]);
    for (var i = 0; i + 2 < p.p.length; i += 3) {
      b[0] = Math.min(b[0], p.p[i]), b[1] = Math.min(b[1], p.p[i + 1]), b[2] = Math.max(b[2], p.p[i]), b[3] = Math.max(b[3], p.p[i + 1]);
    }
  });
  Object.keys(spans).forEach(function (ws) {
    var b = spans[ws];
    if (Math.max(b[2] - b[0], b[3] - b[1]) > size / 50) used[data.colours[Number(ws) % data.colours.length]] = 0;
  });
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
  if (location.hash === '#selftest') selftest();
})();
