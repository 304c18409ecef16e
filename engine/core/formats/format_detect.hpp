// Recognises the external file formats Maris reads (or knows of) from their first lines, so that a file given
// where another kind is expected is named instead of failing on some later line ("row 7: time must increase").
#pragma once

#include <string>
#include <string_view>

namespace maris::formats {

enum class FileFormat {
  table,          // anything else: CSV or whitespace-separated numbers (core/table_reader.hpp)
  peer_at2,       // PEER strong-motion record: 3–4 header lines, "NPTS=…, DT=…", accelerations in g
  wamit_numeric,  // WAMIT numeric output (.1, .3, ...) with its "WAMIT Numeric Output" header line
  wamit_out,      // WAMIT text report (.out)
  tecplot,        // Tecplot ASCII (Nemoh's RadiationCoefficients.tec / ExcitationForce.tec, Capytaine's export)
  netcdf,         // NetCDF / HDF5 (Capytaine's native dataset): binary, not read
};

FileFormat detectFormat(std::string_view text);

// "a PEER NGA .AT2 accelerogram", "WAMIT numeric output (.1/.3)", ...; "" for table.
std::string formatName(FileFormat format);

}  // namespace maris::formats
