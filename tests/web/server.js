// SPDX-License-Identifier: MIT
// A local server for the browser pages (node's http module alone): serves
// the files under --root on 127.0.0.1; with --out, takes the test page's
// results (POST /result/NAME writes DIR/NAME, POST /log prints a line,
// POST /done ends the run with status 0). --timeout SECONDS ends a run that
// never reports done with status 3. --port 0 picks a free port; the first
// line printed is "listening on http://127.0.0.1:PORT/".
'use strict';
const http = require('http');
const fs = require('fs');
const path = require('path');

const args = {};
for (let i = 2; i + 1 < process.argv.length; i += 2)
  args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const root = path.resolve(args.root || '.');
const out = args.out ? path.resolve(args.out) : null;
const types = {
  '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
  '.css': 'text/css', '.png': 'image/png', '.txt': 'text/plain',
};

function body(req, done) {
  const parts = [];
  req.on('data', (c) => parts.push(c));
  req.on('end', () => done(Buffer.concat(parts)));
}

const server = http.createServer((req, res) => {
  const url = decodeURIComponent(req.url.split('?')[0]);
  if (req.method === 'POST' && out) {
    body(req, (data) => {
      if (url === '/done') {
        res.end('ok');
        server.close();
        setImmediate(() => process.exit(0));
      } else if (url === '/log') {
        process.stdout.write(data.toString() + '\n');
        res.end('ok');
      } else if (/^\/result\/[A-Za-z0-9._-]+$/.test(url)) {
        fs.writeFileSync(path.join(out, url.slice(8)), data);
        res.end('ok');
      } else {
        res.statusCode = 404;
        res.end();
      }
    });
    return;
  }
  const file = path.join(root, path.normalize(url === '/' ? '/index.html' : url));
  if (!file.startsWith(root) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.statusCode = 404;
    res.end('not found');
    return;
  }
  res.setHeader('Content-Type', types[path.extname(file)] || 'application/octet-stream');
  fs.createReadStream(file).pipe(res);
});

server.listen(Number(args.port || 0), '127.0.0.1', () => {
  console.log(`listening on http://127.0.0.1:${server.address().port}/`);
});
if (args.timeout)
  setTimeout(() => {
    console.log(`server: no result after ${args.timeout} s`);
    process.exit(3);
  }, Number(args.timeout) * 1000).unref();
