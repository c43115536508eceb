import { readFile } from 'node:fs/promises';
import path from 'node:path';

const content_types = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.map': 'application/json',
  '.json': 'application/json',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
};

// Answers GET requests with files under `root` ('/' is index.html), as the C++ back ends do.
export function staticFiles(root) {
  return async (request, response) => {
    const url = new URL(request.url, 'http://localhost');
    const relative = decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname);
    const file = path.join(root, path.normalize(relative));
    if (!file.startsWith(root + path.sep) || request.method !== 'GET') {
      response.writeHead(404).end('not found\n');
      return;
    }
    try {
      const body = await readFile(file);
      response.writeHead(200, { 'content-type': content_types[path.extname(file)] ?? 'application/octet-stream', 'cache-control': 'no-store' });
      response.end(body);
    } catch {
      response.writeHead(404).end('not found\n');
    }
  };
}
