// The course page's entry: Python first (the report runtime, shared with the calculator's tabs).
import { startRuntime } from '../runtime';
import { CoursePage } from './page';

const page = new CoursePage(document.getElementById('app')!, startRuntime('report'));
void page.start();
