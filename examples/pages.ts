/**
 * The list of example pages: the one place to register a page. `vite.config.ts` builds one HTML
 * entry per item (`<dir>/index.html`) and the site's index page shows one card per item, in this
 * order. To add a page, add its folder and one entry here (see README.md).
 */

/** One page of the examples site. */
export interface ExamplePage {
  /** Folder under examples/ holding the page's index.html; also its URL path (`/<dir>/`). */
  readonly dir: string;
  /** Title on the card (and, by convention, the page's <h1>). */
  readonly title: string;
  /** One line on the card: what the page shows. */
  readonly summary: string;
}

/** Every page, in the order of the index. */
export const pages: readonly ExamplePage[] = [
  {
    dir: 'plugin',
    title: 'The five steps',
    summary: "Physijs's interface in PhysiN: a stack of boxes, a ball thrown at it, an octahedron read from its geometry.",
  },
  {
    dir: 'rotors',
    title: 'Rotors that stay rotations',
    summary: 'A tesseract in a 4D double rotation: why normalising a rotor is not enough, and what rotorCorrect does.',
  },
];
