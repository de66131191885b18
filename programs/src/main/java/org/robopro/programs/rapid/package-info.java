/**
 * RAPID source as a syntax tree: lexer, parser ({@link org.robopro.programs.rapid.RapidAstParser},
 * the whole kernel grammar with source positions), the tree ({@link org.robopro.programs.rapid.RapidAst})
 * and its writer ({@link org.robopro.programs.rapid.RapidAstWriter}); names and number literals
 * chosen so that a written module reads back to the same values (docs/rapid.md). Knows nothing of
 * the typed program model built on it.
 */
package org.robopro.programs.rapid;
