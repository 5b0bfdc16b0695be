// Reads an XML journal into a typed Job. The format is documented in
// docs/journal.md and docs/cooperage-journal.xsd; examples live in examples/.
#pragma once

#include "framework/io/job.h"

#include <string>

namespace cooperage::io {

/// Reads and validates the journal at `path`.
/// Job::file is `path` as given; Job::base_dir is the absolute directory of
/// the journal, against which the executor resolves relative file names.
/// @param[in] path  journal file name
/// @throws MeshingError  FileNotFound when the file cannot be read,
///   ParseError for malformed XML ("<file>:<line>: ..."), InvalidInput for
///   anything the format does not allow ("<file>:<line>: <element>: ...").
Job read_journal(const std::string& path);

/// Parses and validates journal text already in memory.
/// @param[in] xml_text                 the XML document
/// @param[in] file_name_for_messages   stored in Job::file and every SourceLocation
/// @param[in] base_dir                 stored in Job::base_dir, as given
/// @throws MeshingError  ParseError or InvalidInput, as read_journal().
Job parse_journal(const std::string& xml_text, const std::string& file_name_for_messages,
                  const std::string& base_dir);

}  // namespace cooperage::io
