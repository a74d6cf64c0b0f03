// A small LEF library for DEF import tests and benchmarks (io/lefdef.h): layer m2, a via, a pad
// cell and a bump. Shared by tests/io/lefdef_test.cpp and bench/bench_import.cpp.
#pragma once

namespace taut::test {

// A cell 30 x 10 um with pin P at (1, 2)-(3, 4), an obstruction, and a bump 45 x 45 um.
inline constexpr const char* kLef = R"(VERSION 5.8 ;
UNITS
  DATABASE MICRONS 1000 ;
END UNITS
LAYER m2
  TYPE ROUTING ;
END m2
VIA V12 DEFAULT
  LAYER m1 ; RECT -1 -1 1 1 ;
  LAYER m2 ; RECT -2 -1 2 1 ;
END V12
MACRO CELL
  CLASS PAD ;
  ORIGIN 0 0 ;
  SIZE 30 BY 10 ;
  PIN P
    DIRECTION INOUT ;
    PORT
      LAYER m2 ;
        RECT 1 2 3 4 ;
      LAYER m1 ;
        RECT 0 0 30 10 ;
    END
  END P
  PIN VDD
    USE POWER ;
    PORT
      LAYER m2 ;
        RECT 20 2 22 4 ;
    END
  END VDD
  OBS
    LAYER m2 ;
      RECT 10 5 12.5 6 ;
  END
END CELL
MACRO BUMP
  CLASS COVER BUMP ;
  ORIGIN 22.5 22.5 ;
  SIZE 45 BY 45 ;
  PIN PAD
    PORT
      LAYER m2 ;
        POLYGON 22.5 0 0 22.5 -22.5 0 0 -22.5 ;
    END
  END PAD
END BUMP
END LIBRARY
)";

}  // namespace taut::test
