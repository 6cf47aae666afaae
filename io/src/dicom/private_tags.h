#pragma once
// Private attributes (PS3.5 7.8.1): a creator reserves a block of 256 elements of a group by
// writing its name into (gggg,00xx); its element yy is then (gggg,xxyy). The block differs
// from file to file, so a private attribute is found by its creator's name, never by number.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcitem.h>

#include <optional>
#include <string>

namespace voxray::dicom {

// The tag of element ELEMENT (its low byte) in the block CREATOR reserved in GROUP of ITEM.
std::optional<DcmTagKey> privateTag(DcmItem* item, Uint16 group, const char* creator,
                                    Uint8 element);

// The text of that attribute (trailing spaces removed), read as text also when a reader
// without the vendor's dictionary left it as bytes (UN); empty when absent.
std::string privateText(DcmItem* item, Uint16 group, const char* creator, Uint8 element);

}  // namespace voxray::dicom
