// The load test's clients in a node process of their own, no browser:
//   node load_clients.mjs WS_URL N SECS   (node 20: --experimental-websocket)
// Prints one JSON line: the clients' counts (see load_count.mjs) and the
// CPU seconds this process used.
import { countStates } from './load_count.mjs';

const [url, n, secs] = process.argv.slice(2);
const counts = await countStates({ url, n: Number(n), secs: Number(secs) });
const u = process.cpuUsage();
process.stdout.write(`${JSON.stringify({ counts, cpu_s: (u.user + u.system) / 1e6 })}\n`);
process.exit(0);
