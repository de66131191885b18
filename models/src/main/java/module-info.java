/**
 * Robot and cell descriptions, the shared file handling (text, JSON, whole-or-nothing output) and
 * the error type for bad user input. The bottom of the module graph.
 */
module org.robopro.models {
    requires transitive com.fasterxml.jackson.databind;

    exports org.robopro.models;
}
