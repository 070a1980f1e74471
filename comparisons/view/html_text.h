#pragma once
/// Text placed into an HTML page: io::escaped_text (control bytes and malformed UTF-8 shown as
/// \xNN), then & < > " ' as character references, so that it is text in an element's content or
/// in a quoted attribute value, never markup. Every id, engine name, file name and claim that
/// came from a user's file goes into a page through this.
#include <string>
#include <string_view>

namespace tecido::view {

std::string html_text(std::string_view text);

}  // namespace tecido::view
