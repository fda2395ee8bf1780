// Reading NPZ files (what numpy.savez writes and manyworlds' Recorder streams,
// docs/recording.md) in plain JavaScript: a ZIP of stored (uncompressed)
// members "<name>.npy", each in NPY format. Compressed members (numpy's
// savez_compressed) are refused with a message: the browser has no inflate
// we may rely on without a library.
"use strict";

var ManyworldsNpz = (function () {
  function fail(message) {
    throw new Error("NPZ: " + message);
  }

  // Byte offsets above 2^53 cannot occur in an ArrayBuffer; ZIP64 fields are
  // read as two 32-bit halves.
  function u64(view, at) {
    return view.getUint32(at, true) + view.getUint32(at + 4, true) * 4294967296;
  }

  function findEndRecord(view) {
    // The end record is 22 bytes plus a comment of at most 65535 bytes.
    var lowest = Math.max(0, view.byteLength - 22 - 65535);
    for (var at = view.byteLength - 22; at >= lowest; at--) {
      if (view.getUint32(at, true) === 0x06054b50) return at;
    }
    fail("no ZIP end record: not an NPZ file");
  }

  // The members of a ZIP as {name: Uint8Array of its stored bytes}, from
  // the central directory (ZIP64 records and extra fields included).
  function readZip(buffer) {
    var view = new DataView(buffer);
    var end = findEndRecord(view);
    var entries = view.getUint16(end + 10, true);
    var directory = view.getUint32(end + 16, true);
    if (directory === 0xffffffff || entries === 0xffff) {
      var locator = end - 20;
      if (locator < 0 || view.getUint32(locator, true) !== 0x07064b50) fail("bad ZIP64 locator");
      var record = u64(view, locator + 8);
      if (view.getUint32(record, true) !== 0x06064b50) fail("bad ZIP64 end record");
      entries = u64(view, record + 32);
      directory = u64(view, record + 48);
    }
    var members = {};
    var at = directory;
    for (var e = 0; e < entries; e++) {
      if (view.getUint32(at, true) !== 0x02014b50) fail("bad central directory entry " + e);
      var method = view.getUint16(at + 10, true);
      var size = view.getUint32(at + 20, true);
      var uncompressed = view.getUint32(at + 24, true);
      var nameLength = view.getUint16(at + 28, true);
      var extraLength = view.getUint16(at + 30, true);
      var commentLength = view.getUint16(at + 32, true);
      var offset = view.getUint32(at + 42, true);
      var name = new TextDecoder().decode(new Uint8Array(buffer, at + 46, nameLength));
      // ZIP64 extra (id 1): the fields that are 0xffffffff above, in order.
      for (var x = at + 46 + nameLength; x < at + 46 + nameLength + extraLength;) {
        var id = view.getUint16(x, true), length = view.getUint16(x + 2, true);
        if (id === 1) {
          var field = x + 4;
          if (uncompressed === 0xffffffff) { uncompressed = u64(view, field); field += 8; }
          if (size === 0xffffffff) { size = u64(view, field); field += 8; }
          if (offset === 0xffffffff) { offset = u64(view, field); }
        }
        x += 4 + length;
      }
      if (method !== 0) fail("member " + name + " is compressed (numpy.savez_compressed?); only stored members are read");
      if (view.getUint32(offset, true) !== 0x04034b50) fail("bad local header of " + name);
      var data = offset + 30 + view.getUint16(offset + 26, true) + view.getUint16(offset + 28, true);
      members[name] = new Uint8Array(buffer, data, size);
      at += 46 + nameLength + extraLength + commentLength;
    }
    return members;
  }

  var TYPED = {
    "<f4": Float32Array, "<f8": Float64Array, "<i4": Int32Array, "<u4": Uint32Array,
    "<i2": Int16Array, "<u2": Uint16Array, "|u1": Uint8Array, "|i1": Int8Array,
    "<u1": Uint8Array, "|b1": Uint8Array,
  };

  // One NPY array: {dtype, shape, data}; data is a typed array (a copy when
  // the member is not aligned for it), 64-bit integers become Float64Array
  // (exact below 2^53), and '<U' strings an Array of strings.
  function readNpy(bytes, name) {
    if (bytes[0] !== 0x93 || String.fromCharCode.apply(null, bytes.subarray(1, 6)) !== "NUMPY") {
      fail(name + " is not an NPY array");
    }
    var view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    var major = bytes[6];
    var headerLength = major === 1 ? view.getUint16(8, true) : view.getUint32(8, true);
    var headerStart = major === 1 ? 10 : 12;
    var header = new TextDecoder().decode(bytes.subarray(headerStart, headerStart + headerLength));
    var descr = /'descr':\s*'([^']+)'/.exec(header);
    var shapeText = /'shape':\s*\(([^)]*)\)/.exec(header);
    if (!descr || !shapeText) fail(name + ": unreadable NPY header " + header);
    if (/'fortran_order':\s*True/.test(header)) fail(name + ": Fortran order is not read");
    var shape = shapeText[1].split(",").map(function (s) { return s.trim(); })
      .filter(function (s) { return s.length > 0; }).map(Number);
    var count = shape.reduce(function (a, b) { return a * b; }, 1);
    var body = bytes.subarray(headerStart + headerLength);
    var dtype = descr[1];
    var data;
    if (/^<U\d+$/.test(dtype)) {
      var width = Number(dtype.slice(2));
      data = [];
      var words = new DataView(body.buffer, body.byteOffset, body.byteLength);
      for (var i = 0; i < count; i++) {
        var text = "";
        for (var k = 0; k < width; k++) {
          var code = words.getUint32((i * width + k) * 4, true);
          if (code === 0) break;  // numpy pads with zeros
          text += String.fromCodePoint(code);
        }
        data.push(text);
      }
    } else if (dtype === "<i8" || dtype === "<u8") {
      data = new Float64Array(count);
      var longs = new DataView(body.buffer, body.byteOffset, body.byteLength);
      for (var j = 0; j < count; j++) {
        var low = longs.getUint32(j * 8, true), high = longs.getInt32(j * 8 + 4, true);
        data[j] = high * 4294967296 + low;
      }
    } else if (TYPED[dtype]) {
      var Type = TYPED[dtype];
      var copy = new Uint8Array(count * Type.BYTES_PER_ELEMENT);
      copy.set(body.subarray(0, copy.length));  // aligned, whatever the member's offset
      data = new Type(copy.buffer);
    } else {
      fail(name + ": dtype " + dtype + " is not read");
    }
    return { dtype: dtype, shape: shape, data: data };
  }

  // {name: {dtype, shape, data}} of every "<name>.npy" member.
  function parse(buffer) {
    var members = readZip(buffer);
    var arrays = {};
    Object.keys(members).forEach(function (file) {
      if (!/\.npy$/.test(file)) return;
      var name = file.slice(0, -4);
      arrays[name] = readNpy(members[file], name);
    });
    return arrays;
  }

  return { parse: parse };
})();
