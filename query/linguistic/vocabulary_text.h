#pragma once
// The text of schema/vocabulary.json, embedded at build time (query/linguistic/vocabulary_embed.cpp.in).
namespace fsdb {
const char* builtinVocabularyText();
}
