import type { Server } from 'node:http';
/** Serves the files under `root` on 127.0.0.1 at a free port. */
export function serveStatic(root: string): Promise<{ server: Server; base: string }>;
