// The postMessage protocol between an embedded panel (the `?embed=` page in an iframe) and the
// page that holds the iframe (embed.js's <pu-lab-panel>, or a hand-written listener in a wiki
// macro). Every message carries `source: 'pu-lab'` so a host can tell ours from other frames'.
// Types only: embed.js must stay one self-contained file, so each side checks what it reads.
import type { NumbersSource } from '../page/numbers';

/** The frame's document height changed (CSS px, rounded up): set the iframe's height to it. */
export interface SizeMessage { source: 'pu-lab'; type: 'size'; height: number }
/** The numbers shown changed: where they come from (`data-numbers`) and the panel's report. */
export interface ReportMessage { source: 'pu-lab'; type: 'report'; panel: string; numbers: NumbersSource; report: unknown }
/** Frame → host. */
export type FrameMessage = SizeMessage | ReportMessage;
/** Host → frame: follow the host's light/dark scheme. */
export interface ThemeMessage { source: 'pu-lab'; type: 'theme'; theme: Theme }
export type Theme = 'light' | 'dark';
