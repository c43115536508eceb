#pragma once
// The little XML an MD block's comment needs: the text of an element, entities resolved.

#include <string>
#include <string_view>

namespace duet::mdf4 {

// The content of the first <name> element (attributes allowed), entities resolved; "" if there is none.
std::string element_text(std::string_view xml, std::string_view name);
// An MD comment's <TX>, or the XML itself if it has none.
std::string text_of_xml(std::string_view xml);

}  // namespace duet::mdf4
