// Starts tests/mock_backend.mjs on a free port and resolves with its URL and a stop function.
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

export const tests_folder = path.join(path.dirname(fileURLToPath(import.meta.url)), '..');

export function startMock(extraArguments = []) {
  const child = spawn(process.execPath, [path.join(tests_folder, 'mock_backend.mjs'), '--port', '0', ...extraArguments], { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve, reject) => {
    let output = '';
    child.stdout.on('data', (chunk) => {
      output += chunk;
      const match = output.match(/listening (http:\/\/\S+)/);
      if (match) resolve({ url: match[1], stop: () => child.kill('SIGTERM') });
    });
    child.on('exit', (code) => reject(new Error(`the mock back end exited (${code}) before listening`)));
  });
}

// Runs one of the test scripts to completion: {code, stdout, stderr}.
export function runScript(script, args) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, [path.join(tests_folder, script), ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (chunk) => (stdout += chunk));
    child.stderr.on('data', (chunk) => (stderr += chunk));
    child.on('exit', (code) => resolve({ code, stdout, stderr }));
  });
}
