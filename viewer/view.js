// The 3D view of a recording (three.js r111, Debian's libjs-three): one mesh
// per body and world (its collision shape where it has one, else a look
// from its mass properties: viewer/shapes.js), joints as lines from each
// body's centre of mass to the anchor, worlds side by side (offset along X)
// or overlaid (tinted per world), a ground grid under the lowest body unless
// a plane shape faces up, and a camera that frames the whole recording and
// then stays put, so motion shows as motion.
"use strict";

var ManyworldsView = (function () {
  var BACKGROUND = 0x1d2127;
  var STATIC_COLOR = 0x8a9099;
  var JOINT_COLOR = 0xf4f4f0;

  // Saturated, well separated hues for bodies; a world's tint in overlay.
  function bodyColor(THREE, body, world, overlay) {
    var hue = overlay ? (world * 0.17 + 0.02) % 1 : (body * 0.137 + 0.05) % 1;
    var lightness = overlay ? 0.55 : 0.5 + 0.08 * ((body % 3) - 1);
    return new THREE.Color().setHSL(hue, 0.75, lightness);
  }

  function View(THREE, container) {
    this.THREE = THREE;
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(BACKGROUND);
    container.appendChild(this.renderer.domElement);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.controls = THREE.OrbitControls ? new THREE.OrbitControls(this.camera, this.renderer.domElement) : null;
    if (this.controls) this.controls.addEventListener("change", this.render.bind(this));
    this.scene = null;
    this.resize();
  }

  View.prototype.resize = function () {
    var width = this.container.clientWidth || 480, height = this.container.clientHeight || 320;
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    if (this.scene) this.render();
  };

  // Builds the meshes of `recording` for the recorded world slots `slots`,
  // laid out "side" by side or as an "overlay".
  View.prototype.show = function (recording, slots, layout) {
    var THREE = this.THREE;
    this.recording = recording;
    this.slots = slots;
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    var sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(0.4, 1, 0.7);
    this.scene.add(sun);

    // Each body's look and where it sits in the body frame: the collision
    // shape at its position and rotation, else the mass-based look turned
    // onto the principal axes.
    var shapes = [], places = [], radius = [];
    for (var b = 0; b < recording.bodies; b++) {
      var collision = recording.shape(b);
      var drawn = collision ? ManyworldsShapes.fromCollision(collision) : null;
      if (drawn) {
        shapes.push(drawn);
        places.push({ position: collision.position, rotation: collision.rotation });
      } else {
        shapes.push(ManyworldsShapes.fromMass(recording.mass(b), recording.inertiaDiagonal(b),
                                              recording.isStatic(b)));
        places.push({ position: [0, 0, 0], rotation: recording.inertiaRotation(b) });
      }
      var at = places[b].position;
      radius.push(ManyworldsShapes.boundingRadius(shapes[b]) + Math.hypot(at[0], at[1], at[2]));
    }
    this.shapes = shapes;
    // Where one world's bodies go over the whole recording (about 100
    // frames sampled): the spacing of side-by-side worlds and the camera's
    // frame, so nothing leaves the view while it plays.
    var low = [Infinity, Infinity, Infinity], high = [-Infinity, -Infinity, -Infinity];
    var stride = Math.max(1, Math.floor(recording.frames / 100));
    for (var t = 0; t < recording.frames; t += stride) {
      slots.forEach(function (w) {
        for (var b = 0; b < recording.bodies; b++) {
          var p = recording.position(t, w, b);
          if (!isFinite(p[0] + p[1] + p[2])) continue;  // an unhealthy world's NaNs
          for (var k = 0; k < 3; k++) {
            low[k] = Math.min(low[k], p[k] - radius[b]);
            high[k] = Math.max(high[k], p[k] + radius[b]);
          }
        }
      });
    }
    var overlay = layout === "overlay" || slots.length === 1;
    var spacing = 1.25 * (high[0] - low[0]) + 0.2;
    this.offsets = slots.map(function (w, i) { return overlay ? 0 : (i - (slots.length - 1) / 2) * spacing; });

    // A plane spans the worlds laid side by side, with PLANE_SIZE / 2 of
    // ground past the outer ones (whole metres, so that grid cells are 1 m).
    var span = overlay ? 0 : spacing * (slots.length - 1);
    var planeSize = 2 * Math.ceil((ManyworldsShapes.PLANE_SIZE + span) / 2);

    this.meshes = [];
    this.shapeMeshes = [];
    this.colors = [];
    for (var i = 0; i < slots.length; i++) {
      var row = [], colorRow = [], shapeRow = [];
      for (var body = 0; body < recording.bodies; body++) {
        var color = recording.isStatic(body) ? new THREE.Color(STATIC_COLOR)
                                             : bodyColor(THREE, body, i, layout === "overlay");
        var material = new THREE.MeshLambertMaterial({
          color: color, transparent: overlay && slots.length > 1, opacity: overlay && slots.length > 1 ? 0.7 : 1,
        });
        var mesh = new THREE.Group();
        var shape = shapes[body].kind === "plane" ? { kind: "plane", size: planeSize } : shapes[body];
        var placed = ManyworldsShapes.makeMesh(THREE, shape, material);
        var p = places[body].position, q = places[body].rotation;
        placed.position.set(p[0], p[1], p[2]);
        placed.quaternion.set(q[0], q[1], q[2], q[3]);
        mesh.add(placed);
        this.scene.add(mesh);
        row.push(mesh);
        shapeRow.push(placed);
        colorRow.push("#" + color.getHexString());
      }
      this.meshes.push(row);
      this.shapeMeshes.push(shapeRow);
      this.colors.push(colorRow);
    }
    var groundPlane = this.mergePlanes(shapes);

    var segments = recording.constraints * slots.length * 2;
    this.jointPositions = new Float32Array(segments * 2 * 3);
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(this.jointPositions, 3));
    this.joints = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: JOINT_COLOR }));
    this.scene.add(this.joints);

    if (!groundPlane) {
      var grid = new THREE.GridHelper(Math.max(4, 2 * (high[0] - low[0] + spacing * slots.length)), 20,
                                      0x4a525c, 0x323840);
      grid.position.y = low[1];
      this.scene.add(grid);
    }
    this.frameCamera(low, high, spacing * (overlay ? 0 : slots.length - 1));
  };

  // Worlds side by side along X share a ground plane: one plane is drawn
  // for each distinct plane (normal and offset, at frame 0: planes are on
  // static bodies), the shown world's nearest the middle; the others are
  // hidden, so that overlapping see-through squares do not add up. Returns
  // whether a drawn plane faces up (the grid under the lowest body is then
  // left out).
  View.prototype.mergePlanes = function (shapes) {
    var THREE = this.THREE, r = this.recording, self = this, drawn = [];
    var order = this.slots.map(function (w, i) { return i; });
    order.sort(function (a, b) { return Math.abs(self.offsets[a]) - Math.abs(self.offsets[b]); });
    order.forEach(function (i) {
      for (var b = 0; b < r.bodies; b++) {
        if (shapes[b].kind !== "plane") continue;
        var placed = self.shapeMeshes[i][b];
        var p = r.position(0, self.slots[i], b), q = r.rotation(0, self.slots[i], b);
        var body = new THREE.Quaternion(q[0], q[1], q[2], q[3]);
        var normal = new THREE.Vector3(0, 1, 0).applyQuaternion(placed.quaternion).applyQuaternion(body);
        var point = placed.position.clone().applyQuaternion(body).add(
          new THREE.Vector3(p[0] + self.offsets[i], p[1], p[2]));
        var offset = normal.dot(point);
        var same = drawn.some(function (d) {
          return d.normal.distanceTo(normal) < 1e-4 && Math.abs(d.offset - offset) < 1e-4;
        });
        if (same) placed.visible = false;
        else drawn.push({ normal: normal, offset: offset });
      }
    });
    return drawn.some(function (d) { return d.normal.y > 0.9; });
  };

  View.prototype.frameCamera = function (low, high, extraWidth) {
    var THREE = this.THREE;
    var centre = new THREE.Vector3((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2);
    var size = new THREE.Vector3(high[0] - low[0] + extraWidth, high[1] - low[1], high[2] - low[2]);
    var radius = Math.max(0.5 * size.length(), 0.3);
    var fov = THREE.MathUtils ? THREE.MathUtils.degToRad(this.camera.fov) : this.camera.fov * Math.PI / 180;
    var fit = Math.min(fov, 2 * Math.atan(Math.tan(fov / 2) * this.camera.aspect));
    var distance = 1.15 * radius / Math.sin(fit / 2);
    var direction = new THREE.Vector3(0.35, 0.3, 1).normalize();
    this.camera.position.copy(centre).addScaledVector(direction, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.lookAt(centre);
    this.camera.updateProjectionMatrix();
    if (this.controls) {
      this.controls.target.copy(centre);
      this.controls.update();
    }
  };

  // Poses every body of every shown world at frame `t` and draws.
  View.prototype.setFrame = function (t) {
    var r = this.recording, THREE = this.THREE, self = this;
    this.frame = t;
    this.slots.forEach(function (w, i) {
      for (var b = 0; b < r.bodies; b++) {
        var p = r.position(t, w, b), q = r.rotation(t, w, b), mesh = self.meshes[i][b];
        mesh.position.set(p[0] + self.offsets[i], p[1], p[2]);
        mesh.quaternion.set(q[0], q[1], q[2], q[3]);
      }
    });
    var at = 0, anchor = new THREE.Vector3();
    this.slots.forEach(function (w, i) {
      for (var c = 0; c < r.constraints; c++) {
        var bodies = r.constraintBodies(c);
        for (var side = 0; side < 2; side++) {
          var mesh = self.meshes[i][bodies[side]];
          var a = r.anchor(c, side);
          anchor.set(a[0], a[1], a[2]).applyQuaternion(mesh.quaternion).add(mesh.position);
          self.jointPositions.set([mesh.position.x, mesh.position.y, mesh.position.z,
                                   anchor.x, anchor.y, anchor.z], at);
          at += 6;
        }
      }
    });
    this.joints.geometry.attributes.position.needsUpdate = true;
    this.joints.geometry.computeBoundingSphere();
    this.render();
  };

  View.prototype.render = function () {
    if (this.scene) this.renderer.render(this.scene, this.camera);
  };

  // Where each body's centre of mass is drawn, in CSS pixels of the page,
  // with its colour, its collision shape ("none" without one) and what is
  // drawn for it: published for tests (tests/viewer_screenshot_test.py).
  View.prototype.projectedBodies = function () {
    var rect = this.renderer.domElement.getBoundingClientRect(), THREE = this.THREE, self = this;
    var result = [];
    this.slots.forEach(function (w, i) {
      for (var b = 0; b < self.recording.bodies; b++) {
        var p = new THREE.Vector3().copy(self.meshes[i][b].position).project(self.camera);
        result.push({
          world: self.recording.worldIndex[w], body: b, name: self.recording.bodyName[b],
          static: self.recording.isStatic(b), color: self.colors[i][b],
          shape: self.shapes[b].collision ? self.shapes[b].kind : "none", look: self.shapes[b].kind,
          x: rect.left + (p.x + 1) / 2 * rect.width, y: rect.top + (1 - p.y) / 2 * rect.height,
        });
      }
    });
    return result;
  };

  // How many of each kind of shape the scene graph shows ({box: 10, plane:
  // 1, ...}: planes merged across worlds count once), for tests.
  View.prototype.drawnShapes = function () {
    var counts = {};
    if (!this.scene) return counts;
    this.scene.traverseVisible(function (object) {
      var kind = object.userData.manyworldsShape;
      if (kind) counts[kind] = (counts[kind] || 0) + 1;
    });
    return counts;
  };

  return { View: View, BACKGROUND: BACKGROUND };
})();
