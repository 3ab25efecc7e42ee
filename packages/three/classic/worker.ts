/** `physin_worker.js`: the engine's worker entry as one classic script (comlink on `self`). */
import { expose } from 'comlink';
import { WorkerApi } from '../../worker/dist/worker-api.js';

expose(new WorkerApi());
