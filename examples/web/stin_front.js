// SPDX-License-Identifier: MIT
// The page side of the browser front end (platform/web/stin_web.c): loads
// the WebAssembly module, a scene pack and wraps the web_* calls. Shared by
// the demo page (demo.js) and the browser test page (tests/web/test.js).
'use strict';

async function stinFront(canvasSelector, width, height) {
  const m = await createStin({ print: console.log, printErr: console.log });
  const c = (name, ret, args) => m.cwrap(name, ret, args);
  const f = {
    module: m,
    init: c('web_init', 'number', ['string', 'number', 'number']),
    create: c('web_create', 'number', ['string', 'string', 'number', 'number']),
    // for the next create: a technique forced by name ('' forgets them and the options)
    force: c('web_force', 'number', ['string']),
    option: c('web_option', 'number', ['string', 'number']),
    orbit: c('web_orbit', null, ['number', 'number', 'number']),
    frame: c('web_frame', 'number', ['number', 'number']),
    log: () => m.UTF8ToString(m._web_log()),
    choice: () => m.UTF8ToString(m._web_choice()),
    frameStatus: () => m.UTF8ToString(m._web_frame_status()),
    logErrors: () => m._web_log_errors(),
    frameMs: () => m._web_frame_ms(),
    width, height,
  };
  if (!f.init(canvasSelector, width, height)) {
    // say whether the browser has WebGL at all: WebGL 1 alone is refused, not used
    const webgl1 = !!document.createElement('canvas').getContext('webgl');
    throw new Error(m.UTF8ToString(m._web_init_error()) +
                    (webgl1 ? '; this browser gives WebGL 1 only' : '; this browser gives no WebGL'));
  }
  // A scene pack fetched from the server, handed over in a block of the wasm heap.
  f.loadScene = async (url) => {
    const r = await fetch(url);
    if (!r.ok) throw new Error(url + ': ' + r.status);
    const bytes = new Uint8Array(await r.arrayBuffer());
    const p = m._malloc(bytes.length);
    m.HEAPU8.set(bytes, p);
    if (!m._web_scene(p, bytes.length)) throw new Error(url + ': ' + f.log());
  };
  // The offscreen target's colour (what 0) or packed depth (what 1), rows bottom to top.
  f.read = (what) => {
    const n = width * height * 4, p = m._malloc(n);
    const ok = m._web_read(what, p);
    const copy = m.HEAPU8.slice(p, p + n);
    m._free(p);
    return ok ? copy : null;
  };
  f.projection = () => Array.from(m.HEAPF32.subarray(m._web_projection() / 4, m._web_projection() / 4 + 16));
  return f;
}
