/**
 * RAPID source: lexer, parser (syntax tree with source positions) and writer; exported names and
 * numbers chosen so that a written module reads back to the same values (docs/rapid.md).
 */
package org.robopro.programs.rapid;
