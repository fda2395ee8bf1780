// What a body looks like. A body with a collision shape in the recording
// (body_shape_*, docs/recording.md) is drawn as that shape, in the shape's
// frame (placed in the body frame by the view):
//   sphere (1)  -> a sphere of its radius
//   capsule (2) -> a cylinder of length 2 half_height and two hemispheres,
//                  along the shape's Y
//   box (3)     -> a box of twice its half extents
//   plane (4)   -> a flat square (PLANE_SIZE m, or more to span worlds laid
//                  side by side) in the shape's XZ plane, normal (+Y) up: a
//                  grid and a faint, see-through quad that hides nothing
// A body without a shape (and every body of an older recording, which holds
// no shapes) is guessed from its mass properties alone: the solid of uniform
// density whose principal moments match, in the principal frame.
//   three equal moments          -> a sphere (I = 2/5 m r^2)
//   two equal, the third larger  -> a disc, a short cylinder (I_axis = m r^2 / 2)
//   two equal, the third smaller -> a capsule along the odd axis (a rod)
//   otherwise                    -> the box with I_x = m (b^2 + c^2) / 12 ...
// Static bodies (and bodies without mass properties) become small markers.
"use strict";

var ManyworldsShapes = (function () {
  var SAME = 0.03;  // moments within 3 % count as equal
  // ShapeType (include/manyworlds/scene.h) as recorded in body_shape_type.
  var SPHERE = 1, CAPSULE = 2, BOX = 3, PLANE = 4;
  var PLANE_SIZE = 20;  // m, the side of a plane's square
  var PLANE_GRID_COLOR = 0x66707b, PLANE_GRID_CENTRE_COLOR = 0x8a939e;

  function near(a, b) {
    return Math.abs(a - b) <= SAME * Math.max(a, b);
  }

  // {kind: "sphere"|"disc"|"capsule"|"box"|"marker", axis: 0|1|2, radius,
  // length, size: [x, y, z]} in the principal frame.
  function fromMass(mass, inertia, isStatic) {
    var I = inertia;
    if (isStatic || !(mass > 0) || !(I[0] > 0 && I[1] > 0 && I[2] > 0)) {
      return { kind: "marker", size: [0.1, 0.1, 0.1] };
    }
    if (near(I[0], I[1]) && near(I[1], I[2])) {
      return { kind: "sphere", radius: Math.sqrt(2.5 * (I[0] + I[1] + I[2]) / 3 / mass) };
    }
    for (var axis = 0; axis < 3; axis++) {
      var a = I[(axis + 1) % 3], b = I[(axis + 2) % 3], along = I[axis];
      if (!near(a, b)) continue;
      var across = 0.5 * (a + b);
      // A solid cylinder: I_axis = m r^2 / 2, I_across = m (3 r^2 + h^2) / 12.
      var radius = Math.sqrt(2 * along / mass);
      var length = Math.sqrt(Math.max(0, 12 * (across - along / 2) / mass));
      if (along > across) {
        return { kind: "disc", axis: axis, radius: radius, length: Math.max(length, radius / 10) };
      }
      return { kind: "capsule", axis: axis, radius: radius, length: Math.max(length, 2 * radius) };
    }
    var sum = I[0] + I[1] + I[2], size = [];
    for (var k = 0; k < 3; k++) size.push(Math.sqrt(Math.max(0, 6 * (sum - 2 * I[k]) / mass)));
    var largest = Math.max(size[0], size[1], size[2]);
    return { kind: "box", size: size.map(function (s) { return Math.max(s, 0.02 * largest); }) };
  }

  // The drawn shape of a recorded collision shape (Recording.shape: type,
  // size [radius, half_height, half_extents]), in the shape's frame, with
  // `collision: true`; null for a type this viewer does not know (drawn from
  // the mass properties then).
  function fromCollision(shape) {
    var s = shape.size;
    if (shape.type === SPHERE) return { kind: "sphere", radius: s[0], collision: true };
    if (shape.type === CAPSULE) {
      return { kind: "capsule", axis: 1, radius: s[0], length: 2 * (s[1] + s[0]), collision: true };
    }
    if (shape.type === BOX) return { kind: "box", size: [2 * s[2], 2 * s[3], 2 * s[4]], collision: true };
    if (shape.type === PLANE) return { kind: "plane", size: PLANE_SIZE, collision: true };
    return null;
  }

  // A radius that bounds the shape, for framing the camera and spacing worlds.
  // A plane is unbounded: 0, only its centre is framed.
  function boundingRadius(shape) {
    if (shape.kind === "plane") return 0;
    if (shape.kind === "sphere") return shape.radius;
    if (shape.kind === "disc" || shape.kind === "capsule") return Math.hypot(shape.radius, shape.length / 2);
    return 0.5 * Math.hypot(shape.size[0], shape.size[1], shape.size[2]);
  }

  // A grid of `cells` x `cells` in the XZ plane, side `size`, the two centre
  // lines brighter. Unlike three's GridHelper every line is cut into one
  // segment per cell: a line that runs behind the camera is then dropped
  // segment by segment (SwiftShader, at least, drops such a line whole).
  function makeGrid(THREE, size, cells) {
    var positions = [], colors = [], half = size / 2, step = size / cells;
    var centre = new THREE.Color(PLANE_GRID_CENTRE_COLOR), line = new THREE.Color(PLANE_GRID_COLOR);
    for (var k = 0; k <= cells; k++) {
      var across = -half + k * step, color = 2 * k === cells ? centre : line;
      for (var j = 0; j < cells; j++) {
        var from = -half + j * step, to = from + step;
        positions.push(from, 0, across, to, 0, across, across, 0, from, across, 0, to);
        for (var v = 0; v < 4; v++) colors.push(color.r, color.g, color.b);
      }
    }
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(positions, 3));
    geometry.setAttribute("color", new THREE.Float32BufferAttribute(colors, 3));
    // r111 takes the constant THREE.VertexColors, later releases `true`.
    var material = new THREE.LineBasicMaterial({
      vertexColors: THREE.VertexColors !== undefined ? THREE.VertexColors : true,
    });
    return new THREE.LineSegments(geometry, material);
  }

  // A plane's square of side `size` in the XZ plane: a grid of 1 m cells
  // (2 m past 40 m) over a quad of `color`, see-through and not writing depth,
  // so that it hides nothing below it and does not fight the grid.
  function makePlane(THREE, size, color) {
    var group = new THREE.Group();
    group.add(makeGrid(THREE, size, Math.round(size <= 40 ? size : size / 2)));
    var quad = new THREE.Mesh(
      new THREE.PlaneBufferGeometry(size, size),
      new THREE.MeshBasicMaterial({
        color: color, transparent: true, opacity: 0.22, depthWrite: false, side: THREE.DoubleSide,
      }));
    quad.rotation.x = -Math.PI / 2;  // three's plane is XY with normal +Z: onto XZ, normal +Y
    group.add(quad);
    return group;
  }

  // A THREE.Object3D of the shape in its frame (the principal frame for a
  // shape from the mass properties). Cylinders are along three's Y; `axis`
  // turns them onto X or Z. `userData.manyworldsShape` names the kind
  // (the view counts what it draws for tests).
  function makeMesh(THREE, shape, material) {
    var group = makeShapeMesh(THREE, shape, material);
    group.userData.manyworldsShape = shape.kind;
    return group;
  }

  function makeShapeMesh(THREE, shape, material) {
    var group = new THREE.Group();
    if (shape.kind === "plane") return makePlane(THREE, shape.size, material.color);
    if (shape.kind === "sphere") {
      group.add(new THREE.Mesh(new THREE.SphereBufferGeometry(shape.radius, 24, 16), material));
      return group;
    }
    if (shape.kind === "box" || shape.kind === "marker") {
      var s = shape.size;
      group.add(new THREE.Mesh(new THREE.BoxBufferGeometry(s[0], s[1], s[2]), material));
      return group;
    }
    var along = new THREE.Group();
    if (shape.kind === "disc") {
      along.add(new THREE.Mesh(
        new THREE.CylinderBufferGeometry(shape.radius, shape.radius, shape.length, 32), material));
    } else {
      // Capsule (three r111 has no CapsuleGeometry): an open cylinder and
      // two hemispheres, overall length `length`.
      var middle = Math.max(shape.length - 2 * shape.radius, 0);
      along.add(new THREE.Mesh(
        new THREE.CylinderBufferGeometry(shape.radius, shape.radius, middle, 20, 1, true), material));
      [-1, 1].forEach(function (side) {
        // Polar angle from +Y: the top half [0, pi/2], the bottom [pi/2, pi].
        var cap = new THREE.Mesh(new THREE.SphereBufferGeometry(
          shape.radius, 20, 6, 0, 2 * Math.PI, side > 0 ? 0 : Math.PI / 2, Math.PI / 2), material);
        cap.position.y = side * middle / 2;
        along.add(cap);
      });
    }
    if (shape.axis === 0) along.rotation.z = -Math.PI / 2;
    if (shape.axis === 2) along.rotation.x = Math.PI / 2;
    group.add(along);
    return group;
  }

  return {
    fromMass: fromMass, fromCollision: fromCollision, boundingRadius: boundingRadius,
    makeMesh: makeMesh, PLANE_SIZE: PLANE_SIZE,
  };
})();
