// What a body looks like, from its mass properties alone (a recording holds
// no shapes): the solid of uniform density whose principal moments match.
//   three equal moments          -> a sphere (I = 2/5 m r^2)
//   two equal, the third larger  -> a disc, a short cylinder (I_axis = m r^2 / 2)
//   two equal, the third smaller -> a capsule along the odd axis (a rod)
//   otherwise                    -> the box with I_x = m (b^2 + c^2) / 12 ...
// Static bodies (and bodies without mass properties) become small markers.
"use strict";

var ManyworldsShapes = (function () {
  var SAME = 0.03;  // moments within 3 % count as equal

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

  // A radius that bounds the shape, for framing the camera and spacing worlds.
  function boundingRadius(shape) {
    if (shape.kind === "sphere") return shape.radius;
    if (shape.kind === "disc" || shape.kind === "capsule") return Math.hypot(shape.radius, shape.length / 2);
    return 0.5 * Math.hypot(shape.size[0], shape.size[1], shape.size[2]);
  }

  // A THREE.Object3D of the shape in the principal frame. Cylinders are
  // along three's Y; `axis` turns them onto X or Z.
  function makeMesh(THREE, shape, material) {
    var group = new THREE.Group();
    var mesh;
    if (shape.kind === "sphere") {
      mesh = new THREE.Mesh(new THREE.SphereBufferGeometry(shape.radius, 24, 16), material);
      group.add(mesh);
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
      // Capsule (three r111 has no CapsuleGeometry): a cylinder and two
      // spheres, overall length `length`.
      var middle = Math.max(shape.length - 2 * shape.radius, 0);
      along.add(new THREE.Mesh(
        new THREE.CylinderBufferGeometry(shape.radius, shape.radius, middle, 20), material));
      [-1, 1].forEach(function (side) {
        var cap = new THREE.Mesh(new THREE.SphereBufferGeometry(shape.radius, 20, 12), material);
        cap.position.y = side * middle / 2;
        along.add(cap);
      });
    }
    if (shape.axis === 0) along.rotation.z = -Math.PI / 2;
    if (shape.axis === 2) along.rotation.x = Math.PI / 2;
    group.add(along);
    return group;
  }

  return { fromMass: fromMass, boundingRadius: boundingRadius, makeMesh: makeMesh };
})();
