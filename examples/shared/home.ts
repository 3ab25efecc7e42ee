/** The index page: one card per entry of `pages` (its picture from thumbs/), linking to the page's folder. */
import { pages } from '../pages.js';

const list = document.getElementById('pages');
if (!list) throw new Error('index page: element #pages is missing');
for (const page of pages) {
  const item = document.createElement('li');
  item.className = 'card';
  const link = document.createElement('a');
  link.href = `./${page.dir}/`;
  const picture = document.createElement('img');
  picture.src = `./thumbs/${page.dir}.png`;
  picture.alt = '';
  picture.loading = 'lazy';
  const title = document.createElement('h2');
  title.textContent = page.title;
  const summary = document.createElement('p');
  summary.textContent = page.summary;
  link.append(picture, title, summary);
  item.append(link);
  list.append(item);
}
