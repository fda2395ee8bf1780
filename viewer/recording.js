// A recording (docs/recording.md) as the viewer uses it: the NPZ's arrays
// checked against format 1, the bodies' collision shapes (when the file has
// them: older files of format 1 do not), and the pose of any body of any
// recorded world at any frame.
"use strict";

var ManyworldsRecording = (function () {
  var FORMAT_VERSION = 1;
  // The arrays the viewer needs and their shapes (letters are sizes).
  var NEEDED = {
    format_version: [1], time: ["T"], world: ["W"], body_name: ["B"],
    body_motion_type: ["B"], body_mass: ["B"], body_inertia_diagonal: ["B", 3],
    body_inertia_rotation: ["B", 4], position: ["T", "W", "B", 3],
    rotation: ["T", "W", "B", 4], constraint_body: ["C", 2], constraint_anchor: ["C", 2, 3],
    health: ["T", "W"],
  };
  // The bodies' collision shapes: all four arrays or none (files written
  // before shapes were recorded); without them no body has a shape.
  var SHAPE_ARRAYS = {
    body_shape_type: ["B"], body_shape_size: ["B", 5], body_shape_position: ["B", 3],
    body_shape_rotation: ["B", 4],
  };
  var MOTION_STATIC = 0;  // include/manyworlds/motion_type.h

  function check(arrays) {
    Object.keys(NEEDED).forEach(function (name) {
      if (!arrays[name]) throw new Error("not a manyworlds recording: no array '" + name + "'");
    });
    if (arrays.format_version.data[0] !== FORMAT_VERSION) {
      throw new Error("recording format " + arrays.format_version.data[0] + ", this viewer reads " +
                      FORMAT_VERSION);
    }
    var sizes = {
      T: arrays.time.shape[0], W: arrays.world.shape[0], B: arrays.body_name.shape[0],
      C: arrays.constraint_body.shape[0],
    };
    var checkShape = function (name, dims) {
      var expected = dims.map(function (d) { return typeof d === "number" ? d : sizes[d]; });
      if (JSON.stringify(arrays[name].shape) !== JSON.stringify(expected)) {
        throw new Error(name + ": shape " + JSON.stringify(arrays[name].shape) + ", expected " +
                        JSON.stringify(expected));
      }
    };
    Object.keys(NEEDED).forEach(function (name) { checkShape(name, NEEDED[name]); });
    var shapeArrays = Object.keys(SHAPE_ARRAYS);
    if (shapeArrays.some(function (name) { return arrays[name]; })) {
      shapeArrays.forEach(function (name) {
        if (!arrays[name]) throw new Error("the recording has body shapes but no array '" + name + "'");
        checkShape(name, SHAPE_ARRAYS[name]);
      });
    }
    if (sizes.T === 0) throw new Error("the recording has no frame");
    return sizes;
  }

  function Recording(arrays) {
    var sizes = check(arrays);
    this.arrays = arrays;
    this.frames = sizes.T;
    this.worlds = sizes.W;
    this.bodies = sizes.B;
    this.constraints = sizes.C;
    this.scene = arrays.scene ? String(arrays.scene.data[0]) : "";
    this.time = arrays.time.data;
    this.worldIndex = Array.prototype.slice.call(arrays.world.data);
    this.bodyName = arrays.body_name.data;
  }

  Recording.prototype.isStatic = function (body) {
    return this.arrays.body_motion_type.data[body] === MOTION_STATIC;
  };
  Recording.prototype.mass = function (body) {
    return this.arrays.body_mass.data[body];
  };
  Recording.prototype.inertiaDiagonal = function (body) {
    var d = this.arrays.body_inertia_diagonal.data;
    return [d[3 * body], d[3 * body + 1], d[3 * body + 2]];
  };
  Recording.prototype.inertiaRotation = function (body) {
    var q = this.arrays.body_inertia_rotation.data;
    return [q[4 * body], q[4 * body + 1], q[4 * body + 2], q[4 * body + 3]];
  };
  // Whether the file holds the bodies' collision shapes.
  Recording.prototype.hasShapes = function () {
    return Boolean(this.arrays.body_shape_type);
  };
  // The collision shape of `body`, null when it has none (or the file holds
  // no shapes): {type (ShapeType: 1 sphere, 2 capsule, 3 box, 4 plane),
  // size [radius, half_height, half_extents x, y, z], position [x, y, z] and
  // rotation [x, y, z, w] in the body's centre-of-mass frame}.
  Recording.prototype.shape = function (body) {
    if (!this.hasShapes()) return null;
    var type = this.arrays.body_shape_type.data[body];
    if (type === 0) return null;
    var s = this.arrays.body_shape_size.data, p = this.arrays.body_shape_position.data;
    var q = this.arrays.body_shape_rotation.data;
    return {
      type: type, size: Array.prototype.slice.call(s, 5 * body, 5 * body + 5),
      position: Array.prototype.slice.call(p, 3 * body, 3 * body + 3),
      rotation: Array.prototype.slice.call(q, 4 * body, 4 * body + 4),
    };
  };
  // Centre of mass and rotation (x, y, z, w) of `body` in recorded world
  // slot `w` (0 .. worlds-1) at frame `t`.
  Recording.prototype.position = function (t, w, body) {
    var i = ((t * this.worlds + w) * this.bodies + body) * 3, p = this.arrays.position.data;
    return [p[i], p[i + 1], p[i + 2]];
  };
  Recording.prototype.rotation = function (t, w, body) {
    var i = ((t * this.worlds + w) * this.bodies + body) * 4, q = this.arrays.rotation.data;
    return [q[i], q[i + 1], q[i + 2], q[i + 3]];
  };
  Recording.prototype.health = function (t, w) {
    return this.arrays.health.data[t * this.worlds + w];
  };
  Recording.prototype.constraintBodies = function (c) {
    var b = this.arrays.constraint_body.data;
    return [b[2 * c], b[2 * c + 1]];
  };
  // The anchor in body 1's (side 0) or body 2's (side 1) COM frame.
  Recording.prototype.anchor = function (c, side) {
    var a = this.arrays.constraint_anchor.data, i = (2 * c + side) * 3;
    return [a[i], a[i + 1], a[i + 2]];
  };
  // The frame nearest to `seconds` (recorded times are float sums, so
  // "1 s" may be stored as 1.0000001).
  Recording.prototype.frameAt = function (seconds) {
    var low = 0, high = this.frames - 1;
    if (!(seconds >= this.time[0])) return 0;
    while (low < high) {  // the last frame at or before `seconds`
      var middle = (low + high + 1) >> 1;
      if (this.time[middle] <= seconds) low = middle; else high = middle - 1;
    }
    var next = Math.min(low + 1, this.frames - 1);
    return this.time[next] - seconds < seconds - this.time[low] ? next : low;
  };
  Recording.prototype.duration = function () {
    return this.time[this.frames - 1] - this.time[0];
  };

  return {
    fromBuffer: function (buffer) { return new Recording(ManyworldsNpz.parse(buffer)); },
  };
})();
