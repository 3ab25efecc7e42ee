/** three.js as one classic script (`THREE` on the global object), for pages without modules. */
export * from 'three';
