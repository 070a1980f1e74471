#pragma once
/// The content security policy every page carries, as a <meta http-equiv> element: nothing but
/// the page's own files. 'self' is what Chromium matches a file:// page's own folder's files with
/// (checked with Debian's chromium 156: script-src 'self' runs a script beside the page and
/// refuses inline scripts and event-handler attributes). A page that needs no script (report.html)
/// says script-src 'none'.
#include <string>

namespace tecido::view {

/// `with_scripts`: script-src 'self' (the viewer pages); else script-src 'none'.
std::string content_policy_meta(bool with_scripts);

}  // namespace tecido::view
