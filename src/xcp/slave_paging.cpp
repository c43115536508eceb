// The slave's paging commands: each calibration segment has a working page (0, RAM) and a reference page (1, the
// values the firmware was built with, read-only). The ECU page is what the model reads; the XCP page is what the
// master sees at the segment's address.

#include "duet/xcp/slave.hpp"

namespace duet::xcp {
namespace {

constexpr std::uint8_t mode_ecu = 0x01;
constexpr std::uint8_t mode_xcp = 0x02;
constexpr std::uint8_t mode_all = 0x80;
constexpr std::uint8_t page_count = 2;
// GET_PAGE_INFO: ECU access with and without XCP, XCP read access, and for the working page XCP write access.
constexpr std::uint8_t reference_page_properties = 0x01 | 0x02 | 0x04 | 0x08;
constexpr std::uint8_t working_page_properties = reference_page_properties | 0x10 | 0x20;

}  // namespace

Slave::Result Slave::set_cal_page(PacketReader& request, PacketWriter&) {
  const std::uint8_t mode = request.u8();
  const std::uint8_t segment = request.u8();
  const std::uint8_t page = request.u8();
  if ((mode & ~(mode_ecu | mode_xcp | mode_all)) != 0 || (mode & (mode_ecu | mode_xcp)) == 0) {
    return fail(Error::mode_not_valid);
  }
  const std::size_t segments =
      configuration_.segments.size() < max_segments ? configuration_.segments.size() : max_segments;
  const bool all = (mode & mode_all) != 0;
  if (!all && segment >= segments) return fail(Error::segment_not_valid);
  if (page >= page_count) return fail(Error::page_not_valid);
  const std::size_t first = all ? 0 : segment;
  const std::size_t last = all ? segments : static_cast<std::size_t>(segment) + 1;
  if ((mode & mode_ecu) != 0) {  // the model can only switch pages it reads through a pointer
    for (std::size_t index = first; index < last; ++index) {
      if (configuration_.segments[index].ecu_page == nullptr && page != working_page)
        return fail(Error::page_not_valid);
    }
  }
  for (std::size_t index = first; index < last; ++index) {
    const CalibrationSegment& target = configuration_.segments[index];
    if ((mode & mode_xcp) != 0) xcp_page_[index] = page;
    if ((mode & mode_ecu) != 0 && target.ecu_page != nullptr) {
      *target.ecu_page = page == working_page ? target.working : target.reference;  // one pointer store
    }
  }
  return ok;
}

Slave::Result Slave::get_cal_page(PacketReader& request, PacketWriter& response) {
  const std::uint8_t mode = request.u8();
  const std::uint8_t segment = request.u8();
  if (mode != mode_ecu && mode != mode_xcp) return fail(Error::mode_not_valid);
  if (segment >= configuration_.segments.size() || segment >= max_segments) return fail(Error::segment_not_valid);
  const CalibrationSegment& target = configuration_.segments[segment];
  std::uint8_t page = xcp_page_[segment];
  if (mode == mode_ecu) {
    page = target.ecu_page != nullptr && *target.ecu_page == target.reference ? reference_page : working_page;
  }
  response.u8(0).u8(0).u8(page);
  return ok;
}

Slave::Result Slave::get_pag_processor_info(PacketReader&, PacketWriter& response) {
  const std::size_t segments =
      configuration_.segments.size() < max_segments ? configuration_.segments.size() : max_segments;
  response.u8(static_cast<std::uint8_t>(segments)).u8(0);  // no FREEZE mode
  return ok;
}

Slave::Result Slave::get_segment_info(PacketReader& request, PacketWriter& response) {
  const std::uint8_t mode = request.u8();
  const std::uint8_t segment = request.u8();
  const std::uint8_t info = request.u8();
  if (segment >= configuration_.segments.size() || segment >= max_segments) return fail(Error::segment_not_valid);
  const CalibrationSegment& target = configuration_.segments[segment];
  if (mode == 0 && info <= 1) {  // basic: address or length
    response.u8(0).u8(0).u8(0).u32(info == 0 ? target.address : target.size);
    return ok;
  }
  if (mode == 1) {  // standard: pages, address extension, no mapping, no compression, no encryption
    response.u8(page_count).u8(target.extension).u8(0).u8(0).u8(0);
    return ok;
  }
  return fail(Error::out_of_range);  // mapping information: no segment is mapped
}

Slave::Result Slave::get_page_info(PacketReader& request, PacketWriter& response) {
  request.skip(1);
  const std::uint8_t segment = request.u8();
  const std::uint8_t page = request.u8();
  if (segment >= configuration_.segments.size() || segment >= max_segments) return fail(Error::segment_not_valid);
  if (page >= page_count) return fail(Error::page_not_valid);
  response.u8(page == working_page ? working_page_properties : reference_page_properties).u8(segment);
  return ok;
}

Slave::Result Slave::set_segment_mode(PacketReader& request, PacketWriter&) {
  const std::uint8_t mode = request.u8();
  const std::uint8_t segment = request.u8();
  if (segment >= configuration_.segments.size() || segment >= max_segments) return fail(Error::segment_not_valid);
  if (mode != 0) return fail(Error::mode_not_valid);  // FREEZE is not offered
  return ok;
}

Slave::Result Slave::get_segment_mode(PacketReader& request, PacketWriter& response) {
  request.skip(1);
  const std::uint8_t segment = request.u8();
  if (segment >= configuration_.segments.size() || segment >= max_segments) return fail(Error::segment_not_valid);
  response.u8(0).u8(0);
  return ok;
}

// Copies a page onto the working page of the same segment, all at once for the model ("reset to reference").
Slave::Result Slave::copy_cal_page(PacketReader& request, PacketWriter&) {
  const std::uint8_t source_segment = request.u8();
  const std::uint8_t source_page = request.u8();
  const std::uint8_t destination_segment = request.u8();
  const std::uint8_t destination_page = request.u8();
  const std::size_t segments =
      configuration_.segments.size() < max_segments ? configuration_.segments.size() : max_segments;
  if (source_segment >= segments || destination_segment != source_segment) return fail(Error::segment_not_valid);
  if (source_page >= page_count || destination_page >= page_count) return fail(Error::page_not_valid);
  if (destination_page != working_page) return fail(Error::write_protected);
  const CalibrationSegment& target = configuration_.segments[source_segment];
  if (source_page == reference_page) write_memory(target.working, {target.reference, target.size});
  return ok;
}

}  // namespace duet::xcp
