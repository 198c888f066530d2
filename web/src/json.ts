// The two JSON types every layer shares (the page state and the worker protocol): a leaf
// module, so that importing them never pulls in the modules that use them.

/** JSON value. */
export type Json = null | boolean | number | string | Json[] | { [k: string]: Json };

/** The CLI input JSON (docs/contract.md) plus the page's "sim" section. */
export type Input = { [section: string]: { [k: string]: Json } };
