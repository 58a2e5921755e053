module top$fetch(clock,host_write,host_address,host_data,start,valid,cur$0,cur$1,cur$2,cur$3,next$0,next$1,next$2,next$3,ext_addr$0,ext_addr$1,ext_addr$2,ext_addr$3,ext_data$0,ext_data$1,ext_data$2,ext_data$3,load_enable,load_module,load_address,load_data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  start;
    output reg  valid;
    output reg  [15:0] cur$0;
    output reg  [15:0] cur$1;
    output reg  [15:0] cur$2;
    output reg  [15:0] cur$3;
    output reg  [15:0] next$0;
    output reg  [15:0] next$1;
    output reg  [15:0] next$2;
    output reg  [15:0] next$3;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    output reg  [31:0] ext_addr$2;
    output reg  [31:0] ext_addr$3;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    input wire  [15:0] ext_data$2;
    input wire  [15:0] ext_data$3;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [31:0] load_address;
    input wire  [15:0] load_data;
    
    // Constant declarations
    localparam  external = 1'b0;
    localparam  perspective = 1'b0;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  index$2 = 16'h2;
    localparam  index$3 = 16'h3;
    localparam  module_id$0 = 8'h0;
    localparam  module_id$1 = 8'h1;
    localparam  module_id$2 = 8'h2;
    localparam  module_id$3 = 8'h3;
    localparam  buffer_id$0 = 2'b0;
    localparam  buffer_id$1 = 2'b1;
    localparam  buffer_id$2 = 2'b10;
    localparam  one = 16'h1;
    localparam  mask = 16'h3;
    localparam  shift = 16'h2;
    
    // Stub signals
    reg  [15:0] memory$0$read_address;
    reg  memory$0$read_clock;
    wire  [15:0] memory$0$read_data;
    reg  [15:0] memory$0$write_address;
    reg  memory$0$write_clock;
    reg  [15:0] memory$0$write_data;
    reg  memory$0$write_enable;
    reg  [15:0] memory$1$read_address;
    reg  memory$1$read_clock;
    wire  [15:0] memory$1$read_data;
    reg  [15:0] memory$1$write_address;
    reg  memory$1$write_clock;
    reg  [15:0] memory$1$write_data;
    reg  memory$1$write_enable;
    reg  [15:0] memory$2$read_address;
    reg  memory$2$read_clock;
    wire  [15:0] memory$2$read_data;
    reg  [15:0] memory$2$write_address;
    reg  memory$2$write_clock;
    reg  [15:0] memory$2$write_data;
    reg  memory$2$write_enable;
    reg  [15:0] memory$3$read_address;
    reg  memory$3$read_clock;
    wire  [15:0] memory$3$read_data;
    reg  [15:0] memory$3$write_address;
    reg  memory$3$write_clock;
    reg  [15:0] memory$3$write_data;
    reg  memory$3$write_enable;
    reg  [16:0] buffer0$0$read_address;
    reg  buffer0$0$read_clock;
    wire  [15:0] buffer0$0$read_data;
    reg  [16:0] buffer0$0$write_address;
    reg  buffer0$0$write_clock;
    reg  [15:0] buffer0$0$write_data;
    reg  buffer0$0$write_enable;
    reg  [16:0] buffer0$1$read_address;
    reg  buffer0$1$read_clock;
    wire  [15:0] buffer0$1$read_data;
    reg  [16:0] buffer0$1$write_address;
    reg  buffer0$1$write_clock;
    reg  [15:0] buffer0$1$write_data;
    reg  buffer0$1$write_enable;
    reg  [16:0] buffer0$2$read_address;
    reg  buffer0$2$read_clock;
    wire  [15:0] buffer0$2$read_data;
    reg  [16:0] buffer0$2$write_address;
    reg  buffer0$2$write_clock;
    reg  [15:0] buffer0$2$write_data;
    reg  buffer0$2$write_enable;
    reg  [16:0] buffer0$3$read_address;
    reg  buffer0$3$read_clock;
    wire  [15:0] buffer0$3$read_data;
    reg  [16:0] buffer0$3$write_address;
    reg  buffer0$3$write_clock;
    reg  [15:0] buffer0$3$write_data;
    reg  buffer0$3$write_enable;
    reg  [16:0] buffer1$0$read_address;
    reg  buffer1$0$read_clock;
    wire  [15:0] buffer1$0$read_data;
    reg  [16:0] buffer1$0$write_address;
    reg  buffer1$0$write_clock;
    reg  [15:0] buffer1$0$write_data;
    reg  buffer1$0$write_enable;
    reg  [16:0] buffer1$1$read_address;
    reg  buffer1$1$read_clock;
    wire  [15:0] buffer1$1$read_data;
    reg  [16:0] buffer1$1$write_address;
    reg  buffer1$1$write_clock;
    reg  [15:0] buffer1$1$write_data;
    reg  buffer1$1$write_enable;
    reg  [16:0] buffer1$2$read_address;
    reg  buffer1$2$read_clock;
    wire  [15:0] buffer1$2$read_data;
    reg  [16:0] buffer1$2$write_address;
    reg  buffer1$2$write_clock;
    reg  [15:0] buffer1$2$write_data;
    reg  buffer1$2$write_enable;
    reg  [16:0] buffer1$3$read_address;
    reg  buffer1$3$read_clock;
    wire  [15:0] buffer1$3$read_data;
    reg  [16:0] buffer1$3$write_address;
    reg  buffer1$3$write_clock;
    reg  [15:0] buffer1$3$write_data;
    reg  buffer1$3$write_enable;
    reg  [16:0] buffer2$0$read_address;
    reg  buffer2$0$read_clock;
    wire  [15:0] buffer2$0$read_data;
    reg  [16:0] buffer2$0$write_address;
    reg  buffer2$0$write_clock;
    reg  [15:0] buffer2$0$write_data;
    reg  buffer2$0$write_enable;
    reg  [16:0] buffer2$1$read_address;
    reg  buffer2$1$read_clock;
    wire  [15:0] buffer2$1$read_data;
    reg  [16:0] buffer2$1$write_address;
    reg  buffer2$1$write_clock;
    reg  [15:0] buffer2$1$write_data;
    reg  buffer2$1$write_enable;
    reg  [16:0] buffer2$2$read_address;
    reg  buffer2$2$read_clock;
    wire  [15:0] buffer2$2$read_data;
    reg  [16:0] buffer2$2$write_address;
    reg  buffer2$2$write_clock;
    reg  [15:0] buffer2$2$write_data;
    reg  buffer2$2$write_enable;
    reg  [16:0] buffer2$3$read_address;
    reg  buffer2$3$read_clock;
    wire  [15:0] buffer2$3$read_data;
    reg  [16:0] buffer2$3$write_address;
    reg  buffer2$3$write_clock;
    reg  [15:0] buffer2$3$write_data;
    reg  buffer2$3$write_enable;
    reg  group$clock;
    reg  group$host_write;
    reg  [23:0] group$host_address;
    reg  [63:0] group$host_data;
    reg  [15:0] group$u0;
    reg  [23:0] group$chunk;
    reg  [23:0] group$chunk_next;
    reg  [15:0] group$plane_count;
    wire  [15:0] group$plane;
    wire  [15:0] group$first_ray;
    wire  [15:0] group$x$0;
    wire  [15:0] group$x$1;
    wire  [15:0] group$x$2;
    wire  [15:0] group$x$3;
    wire  group$holds$0;
    wire  group$holds$1;
    wire  group$holds$2;
    wire  group$holds$3;
    reg  pos_y$clock;
    reg  pos_y$host_write;
    reg  [23:0] pos_y$host_address;
    reg  [63:0] pos_y$host_data;
    reg  [17:0] pos_y$address;
    wire  [15:0] pos_y$data;
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    wire  [63:0] regs$q$2;
    wire  [63:0] regs$q$3;
    reg  [31:0] row_base_r$d;
    wire  [31:0] row_base_r$q;
    reg  row_base_r$clock;
    reg  schedule$clock;
    reg  schedule$start;
    wire  schedule$writing;
    wire  [15:0] schedule$plane;
    wire  [23:0] schedule$chunk;
    wire  [23:0] schedule$chunk_next;
    wire  [15:0] schedule$period;
    wire  [15:0] schedule$period_next;
    wire  [1:0] schedule$write_buffer;
    wire  schedule$reading;
    wire  [15:0] schedule$ray;
    wire  [31:0] schedule$read_address;
    wire  [1:0] schedule$cur_buffer;
    wire  [1:0] schedule$next_buffer;
    reg  schedule$host_write;
    reg  [23:0] schedule$host_address;
    reg  [63:0] schedule$host_data;
    reg  [15:0] plane_r$d;
    wire  [15:0] plane_r$q;
    reg  plane_r$clock;
    reg  [15:0] first_ray_r$d;
    wire  [15:0] first_ray_r$q;
    reg  first_ray_r$clock;
    reg  [15:0] x_r$0$d;
    wire  [15:0] x_r$0$q;
    reg  x_r$0$clock;
    reg  [15:0] x_r$1$d;
    wire  [15:0] x_r$1$q;
    reg  x_r$1$clock;
    reg  [15:0] x_r$2$d;
    wire  [15:0] x_r$2$q;
    reg  x_r$2$clock;
    reg  [15:0] x_r$3$d;
    wire  [15:0] x_r$3$q;
    reg  x_r$3$clock;
    reg  holds_r$0$d;
    wire  holds_r$0$q;
    reg  holds_r$0$clock;
    reg  holds_r$1$d;
    wire  holds_r$1$q;
    reg  holds_r$1$clock;
    reg  holds_r$2$d;
    wire  holds_r$2$q;
    reg  holds_r$2$clock;
    reg  holds_r$3$d;
    wire  holds_r$3$q;
    reg  holds_r$3$clock;
    reg  [15:0] period_r$d;
    wire  [15:0] period_r$q;
    reg  period_r$clock;
    reg  writing_r$d;
    wire  writing_r$q;
    reg  writing_r$clock;
    reg  [1:0] buffer_r$d;
    wire  [1:0] buffer_r$q;
    reg  buffer_r$clock;
    reg  [15:0] s1_row$d;
    wire  [15:0] s1_row$q;
    reg  s1_row$clock;
    reg  [15:0] s1_plane$d;
    wire  [15:0] s1_plane$q;
    reg  s1_plane$clock;
    reg  [31:0] s1_plane_offset$d;
    wire  [31:0] s1_plane_offset$q;
    reg  s1_plane_offset$clock;
    reg  [15:0] s1_ray$0$d;
    wire  [15:0] s1_ray$0$q;
    reg  s1_ray$0$clock;
    reg  [15:0] s1_ray$1$d;
    wire  [15:0] s1_ray$1$q;
    reg  s1_ray$1$clock;
    reg  [15:0] s1_ray$2$d;
    wire  [15:0] s1_ray$2$q;
    reg  s1_ray$2$clock;
    reg  [15:0] s1_ray$3$d;
    wire  [15:0] s1_ray$3$q;
    reg  s1_ray$3$clock;
    reg  [15:0] s1_x$0$d;
    wire  [15:0] s1_x$0$q;
    reg  s1_x$0$clock;
    reg  [15:0] s1_x$1$d;
    wire  [15:0] s1_x$1$q;
    reg  s1_x$1$clock;
    reg  [15:0] s1_x$2$d;
    wire  [15:0] s1_x$2$q;
    reg  s1_x$2$clock;
    reg  [15:0] s1_x$3$d;
    wire  [15:0] s1_x$3$q;
    reg  s1_x$3$clock;
    reg  s1_holds$0$d;
    wire  s1_holds$0$q;
    reg  s1_holds$0$clock;
    reg  s1_holds$1$d;
    wire  s1_holds$1$q;
    reg  s1_holds$1$clock;
    reg  s1_holds$2$d;
    wire  s1_holds$2$q;
    reg  s1_holds$2$clock;
    reg  s1_holds$3$d;
    wire  s1_holds$3$q;
    reg  s1_holds$3$clock;
    reg  s1_writing$d;
    wire  s1_writing$q;
    reg  s1_writing$clock;
    reg  [1:0] s1_buffer$d;
    wire  [1:0] s1_buffer$q;
    reg  s1_buffer$clock;
    reg  s2_inside$0$d;
    wire  s2_inside$0$q;
    reg  s2_inside$0$clock;
    reg  s2_inside$1$d;
    wire  s2_inside$1$q;
    reg  s2_inside$1$clock;
    reg  s2_inside$2$d;
    wire  s2_inside$2$q;
    reg  s2_inside$2$clock;
    reg  s2_inside$3$d;
    wire  s2_inside$3$q;
    reg  s2_inside$3$clock;
    reg  [15:0] s2_module$0$d;
    wire  [15:0] s2_module$0$q;
    reg  s2_module$0$clock;
    reg  [15:0] s2_module$1$d;
    wire  [15:0] s2_module$1$q;
    reg  s2_module$1$clock;
    reg  [15:0] s2_module$2$d;
    wire  [15:0] s2_module$2$q;
    reg  s2_module$2$clock;
    reg  [15:0] s2_module$3$d;
    wire  [15:0] s2_module$3$q;
    reg  s2_module$3$clock;
    reg  [31:0] s2_address$0$d;
    wire  [31:0] s2_address$0$q;
    reg  s2_address$0$clock;
    reg  [31:0] s2_address$1$d;
    wire  [31:0] s2_address$1$q;
    reg  s2_address$1$clock;
    reg  [31:0] s2_address$2$d;
    wire  [31:0] s2_address$2$q;
    reg  s2_address$2$clock;
    reg  [31:0] s2_address$3$d;
    wire  [31:0] s2_address$3$q;
    reg  s2_address$3$clock;
    reg  s2_holds$0$d;
    wire  s2_holds$0$q;
    reg  s2_holds$0$clock;
    reg  s2_holds$1$d;
    wire  s2_holds$1$q;
    reg  s2_holds$1$clock;
    reg  s2_holds$2$d;
    wire  s2_holds$2$q;
    reg  s2_holds$2$clock;
    reg  s2_holds$3$d;
    wire  s2_holds$3$q;
    reg  s2_holds$3$clock;
    reg  [15:0] s2_dsb$0$d;
    wire  [15:0] s2_dsb$0$q;
    reg  s2_dsb$0$clock;
    reg  [15:0] s2_dsb$1$d;
    wire  [15:0] s2_dsb$1$q;
    reg  s2_dsb$1$clock;
    reg  [15:0] s2_dsb$2$d;
    wire  [15:0] s2_dsb$2$q;
    reg  s2_dsb$2$clock;
    reg  [15:0] s2_dsb$3$d;
    wire  [15:0] s2_dsb$3$q;
    reg  s2_dsb$3$clock;
    reg  [31:0] s2_write_address$0$d;
    wire  [31:0] s2_write_address$0$q;
    reg  s2_write_address$0$clock;
    reg  [31:0] s2_write_address$1$d;
    wire  [31:0] s2_write_address$1$q;
    reg  s2_write_address$1$clock;
    reg  [31:0] s2_write_address$2$d;
    wire  [31:0] s2_write_address$2$q;
    reg  s2_write_address$2$clock;
    reg  [31:0] s2_write_address$3$d;
    wire  [31:0] s2_write_address$3$q;
    reg  s2_write_address$3$clock;
    reg  s2_in_stream$0$d;
    wire  s2_in_stream$0$q;
    reg  s2_in_stream$0$clock;
    reg  s2_in_stream$1$d;
    wire  s2_in_stream$1$q;
    reg  s2_in_stream$1$clock;
    reg  s2_in_stream$2$d;
    wire  s2_in_stream$2$q;
    reg  s2_in_stream$2$clock;
    reg  s2_in_stream$3$d;
    wire  s2_in_stream$3$q;
    reg  s2_in_stream$3$clock;
    reg  s2_writing$d;
    wire  s2_writing$q;
    reg  s2_writing$clock;
    reg  [1:0] s2_buffer$d;
    wire  [1:0] s2_buffer$q;
    reg  s2_buffer$clock;
    reg  holds_q$0$d;
    wire  holds_q$0$q;
    reg  holds_q$0$clock;
    reg  holds_q$1$d;
    wire  holds_q$1$q;
    reg  holds_q$1$clock;
    reg  holds_q$2$d;
    wire  holds_q$2$q;
    reg  holds_q$2$clock;
    reg  holds_q$3$d;
    wire  holds_q$3$q;
    reg  holds_q$3$clock;
    reg  inside_q$0$d;
    wire  inside_q$0$q;
    reg  inside_q$0$clock;
    reg  inside_q$1$d;
    wire  inside_q$1$q;
    reg  inside_q$1$clock;
    reg  inside_q$2$d;
    wire  inside_q$2$q;
    reg  inside_q$2$clock;
    reg  inside_q$3$d;
    wire  inside_q$3$q;
    reg  inside_q$3$clock;
    reg  [15:0] module_q$0$d;
    wire  [15:0] module_q$0$q;
    reg  module_q$0$clock;
    reg  [15:0] module_q$1$d;
    wire  [15:0] module_q$1$q;
    reg  module_q$1$clock;
    reg  [15:0] module_q$2$d;
    wire  [15:0] module_q$2$q;
    reg  module_q$2$clock;
    reg  [15:0] module_q$3$d;
    wire  [15:0] module_q$3$q;
    reg  module_q$3$clock;
    reg  [15:0] dsb_q$0$d;
    wire  [15:0] dsb_q$0$q;
    reg  dsb_q$0$clock;
    reg  [15:0] dsb_q$1$d;
    wire  [15:0] dsb_q$1$q;
    reg  dsb_q$1$clock;
    reg  [15:0] dsb_q$2$d;
    wire  [15:0] dsb_q$2$q;
    reg  dsb_q$2$clock;
    reg  [15:0] dsb_q$3$d;
    wire  [15:0] dsb_q$3$q;
    reg  dsb_q$3$clock;
    reg  [31:0] write_address_q$0$d;
    wire  [31:0] write_address_q$0$q;
    reg  write_address_q$0$clock;
    reg  [31:0] write_address_q$1$d;
    wire  [31:0] write_address_q$1$q;
    reg  write_address_q$1$clock;
    reg  [31:0] write_address_q$2$d;
    wire  [31:0] write_address_q$2$q;
    reg  write_address_q$2$clock;
    reg  [31:0] write_address_q$3$d;
    wire  [31:0] write_address_q$3$q;
    reg  write_address_q$3$clock;
    reg  in_stream_q$0$d;
    wire  in_stream_q$0$q;
    reg  in_stream_q$0$clock;
    reg  in_stream_q$1$d;
    wire  in_stream_q$1$q;
    reg  in_stream_q$1$clock;
    reg  in_stream_q$2$d;
    wire  in_stream_q$2$q;
    reg  in_stream_q$2$clock;
    reg  in_stream_q$3$d;
    wire  in_stream_q$3$q;
    reg  in_stream_q$3$clock;
    reg  write_q$d;
    wire  write_q$q;
    reg  write_q$clock;
    reg  [1:0] buffer_q$d;
    wire  [1:0] buffer_q$q;
    reg  buffer_q$clock;
    reg  read_q$d;
    wire  read_q$q;
    reg  read_q$clock;
    reg  [15:0] lane_q$d;
    wire  [15:0] lane_q$q;
    reg  lane_q$clock;
    reg  [1:0] cur_q$d;
    wire  [1:0] cur_q$q;
    reg  cur_q$clock;
    reg  [1:0] next_q$d;
    wire  [1:0] next_q$q;
    reg  next_q$clock;
    reg  [15:0] cur_m$0$d;
    wire  [15:0] cur_m$0$q;
    reg  cur_m$0$clock;
    reg  [15:0] cur_m$1$d;
    wire  [15:0] cur_m$1$q;
    reg  cur_m$1$clock;
    reg  [15:0] cur_m$2$d;
    wire  [15:0] cur_m$2$q;
    reg  cur_m$2$clock;
    reg  [15:0] cur_m$3$d;
    wire  [15:0] cur_m$3$q;
    reg  cur_m$3$clock;
    reg  [15:0] next_m$0$d;
    wire  [15:0] next_m$0$q;
    reg  next_m$0$clock;
    reg  [15:0] next_m$1$d;
    wire  [15:0] next_m$1$q;
    reg  next_m$1$clock;
    reg  [15:0] next_m$2$d;
    wire  [15:0] next_m$2$q;
    reg  next_m$2$clock;
    reg  [15:0] next_m$3$d;
    wire  [15:0] next_m$3$q;
    reg  next_m$3$clock;
    reg  read_q2$d;
    wire  read_q2$q;
    reg  read_q2$clock;
    reg  [15:0] lane_q2$d;
    wire  [15:0] lane_q2$q;
    reg  lane_q2$clock;
    
    // Local signals
    reg  [15:0] word$0;
    reg  [15:0] word$1;
    reg  [15:0] word$2;
    reg  [15:0] word$3;
    reg  [15:0] row_stride;
    reg  [31:0] row_entry;
    reg  [15:0] s1_plane_segment;
    reg  lane_inside$0;
    reg  lane_inside$1;
    reg  lane_inside$2;
    reg  lane_inside$3;
    reg  [15:0] lane_module$0;
    reg  [15:0] lane_module$1;
    reg  [15:0] lane_module$2;
    reg  [15:0] lane_module$3;
    reg  [15:0] lane_column$0;
    reg  [15:0] lane_column$1;
    reg  [15:0] lane_column$2;
    reg  [15:0] lane_column$3;
    reg  [31:0] lane_address$0;
    reg  [31:0] lane_address$1;
    reg  [31:0] lane_address$2;
    reg  [31:0] lane_address$3;
    reg  [15:0] lane_dsb$0;
    reg  [15:0] lane_dsb$1;
    reg  [15:0] lane_dsb$2;
    reg  [15:0] lane_dsb$3;
    reg  [31:0] lane_write_address$0;
    reg  [31:0] lane_write_address$1;
    reg  [31:0] lane_write_address$2;
    reg  [31:0] lane_write_address$3;
    reg  [31:0] address$0;
    reg  [31:0] address$1;
    reg  [31:0] address$2;
    reg  [31:0] address$3;
    reg  reads$0;
    reg  reads$1;
    reg  reads$2;
    reg  reads$3;
    reg  [15:0] value$0;
    reg  [15:0] value$1;
    reg  [15:0] value$2;
    reg  [15:0] value$3;
    reg  [15:0] dsb_data$0;
    reg  [15:0] dsb_data$1;
    reg  [15:0] dsb_data$2;
    reg  [15:0] dsb_data$3;
    reg  dsb_write$0;
    reg  dsb_write$1;
    reg  dsb_write$2;
    reg  dsb_write$3;
    reg  [31:0] write_address$0;
    reg  [31:0] write_address$1;
    reg  [31:0] write_address$2;
    reg  [31:0] write_address$3;
    reg  [31:0] read_address;
    reg  [15:0] n_x;
    reg  [15:0] n_y;
    reg  [15:0] n_k;
    reg  [15:0] row_words;
    reg  [15:0] plane_words;
    reg  [15:0] v0;
    reg  [15:0] rays;
    reg  [15:0] segments;
    
    // Sub module instances
    top$fetch$memory$0 memory$0(
        .read_address(memory$0$read_address),
        .read_clock(memory$0$read_clock),
        .read_data(memory$0$read_data),
        .write_address(memory$0$write_address),
        .write_clock(memory$0$write_clock),
        .write_data(memory$0$write_data),
        .write_enable(memory$0$write_enable)
    );
    top$fetch$memory$1 memory$1(
        .read_address(memory$1$read_address),
        .read_clock(memory$1$read_clock),
        .read_data(memory$1$read_data),
        .write_address(memory$1$write_address),
        .write_clock(memory$1$write_clock),
        .write_data(memory$1$write_data),
        .write_enable(memory$1$write_enable)
    );
    top$fetch$memory$2 memory$2(
        .read_address(memory$2$read_address),
        .read_clock(memory$2$read_clock),
        .read_data(memory$2$read_data),
        .write_address(memory$2$write_address),
        .write_clock(memory$2$write_clock),
        .write_data(memory$2$write_data),
        .write_enable(memory$2$write_enable)
    );
    top$fetch$memory$3 memory$3(
        .read_address(memory$3$read_address),
        .read_clock(memory$3$read_clock),
        .read_data(memory$3$read_data),
        .write_address(memory$3$write_address),
        .write_clock(memory$3$write_clock),
        .write_data(memory$3$write_data),
        .write_enable(memory$3$write_enable)
    );
    top$fetch$buffer0$0 buffer0$0(
        .read_address(buffer0$0$read_address),
        .read_clock(buffer0$0$read_clock),
        .read_data(buffer0$0$read_data),
        .write_address(buffer0$0$write_address),
        .write_clock(buffer0$0$write_clock),
        .write_data(buffer0$0$write_data),
        .write_enable(buffer0$0$write_enable)
    );
    top$fetch$buffer0$1 buffer0$1(
        .read_address(buffer0$1$read_address),
        .read_clock(buffer0$1$read_clock),
        .read_data(buffer0$1$read_data),
        .write_address(buffer0$1$write_address),
        .write_clock(buffer0$1$write_clock),
        .write_data(buffer0$1$write_data),
        .write_enable(buffer0$1$write_enable)
    );
    top$fetch$buffer0$2 buffer0$2(
        .read_address(buffer0$2$read_address),
        .read_clock(buffer0$2$read_clock),
        .read_data(buffer0$2$read_data),
        .write_address(buffer0$2$write_address),
        .write_clock(buffer0$2$write_clock),
        .write_data(buffer0$2$write_data),
        .write_enable(buffer0$2$write_enable)
    );
    top$fetch$buffer0$3 buffer0$3(
        .read_address(buffer0$3$read_address),
        .read_clock(buffer0$3$read_clock),
        .read_data(buffer0$3$read_data),
        .write_address(buffer0$3$write_address),
        .write_clock(buffer0$3$write_clock),
        .write_data(buffer0$3$write_data),
        .write_enable(buffer0$3$write_enable)
    );
    top$fetch$buffer1$0 buffer1$0(
        .read_address(buffer1$0$read_address),
        .read_clock(buffer1$0$read_clock),
        .read_data(buffer1$0$read_data),
        .write_address(buffer1$0$write_address),
        .write_clock(buffer1$0$write_clock),
        .write_data(buffer1$0$write_data),
        .write_enable(buffer1$0$write_enable)
    );
    top$fetch$buffer1$1 buffer1$1(
        .read_address(buffer1$1$read_address),
        .read_clock(buffer1$1$read_clock),
        .read_data(buffer1$1$read_data),
        .write_address(buffer1$1$write_address),
        .write_clock(buffer1$1$write_clock),
        .write_data(buffer1$1$write_data),
        .write_enable(buffer1$1$write_enable)
    );
    top$fetch$buffer1$2 buffer1$2(
        .read_address(buffer1$2$read_address),
        .read_clock(buffer1$2$read_clock),
        .read_data(buffer1$2$read_data),
        .write_address(buffer1$2$write_address),
        .write_clock(buffer1$2$write_clock),
        .write_data(buffer1$2$write_data),
        .write_enable(buffer1$2$write_enable)
    );
    top$fetch$buffer1$3 buffer1$3(
        .read_address(buffer1$3$read_address),
        .read_clock(buffer1$3$read_clock),
        .read_data(buffer1$3$read_data),
        .write_address(buffer1$3$write_address),
        .write_clock(buffer1$3$write_clock),
        .write_data(buffer1$3$write_data),
        .write_enable(buffer1$3$write_enable)
    );
    top$fetch$buffer2$0 buffer2$0(
        .read_address(buffer2$0$read_address),
        .read_clock(buffer2$0$read_clock),
        .read_data(buffer2$0$read_data),
        .write_address(buffer2$0$write_address),
        .write_clock(buffer2$0$write_clock),
        .write_data(buffer2$0$write_data),
        .write_enable(buffer2$0$write_enable)
    );
    top$fetch$buffer2$1 buffer2$1(
        .read_address(buffer2$1$read_address),
        .read_clock(buffer2$1$read_clock),
        .read_data(buffer2$1$read_data),
        .write_address(buffer2$1$write_address),
        .write_clock(buffer2$1$write_clock),
        .write_data(buffer2$1$write_data),
        .write_enable(buffer2$1$write_enable)
    );
    top$fetch$buffer2$2 buffer2$2(
        .read_address(buffer2$2$read_address),
        .read_clock(buffer2$2$read_clock),
        .read_data(buffer2$2$read_data),
        .write_address(buffer2$2$write_address),
        .write_clock(buffer2$2$write_clock),
        .write_data(buffer2$2$write_data),
        .write_enable(buffer2$2$write_enable)
    );
    top$fetch$buffer2$3 buffer2$3(
        .read_address(buffer2$3$read_address),
        .read_clock(buffer2$3$read_clock),
        .read_data(buffer2$3$read_data),
        .write_address(buffer2$3$write_address),
        .write_clock(buffer2$3$write_clock),
        .write_data(buffer2$3$write_data),
        .write_enable(buffer2$3$write_enable)
    );
    top$fetch$group group(
        .clock(group$clock),
        .host_write(group$host_write),
        .host_address(group$host_address),
        .host_data(group$host_data),
        .u0(group$u0),
        .chunk(group$chunk),
        .chunk_next(group$chunk_next),
        .plane_count(group$plane_count),
        .plane(group$plane),
        .first_ray(group$first_ray),
        .x$0(group$x$0),
        .x$1(group$x$1),
        .x$2(group$x$2),
        .x$3(group$x$3),
        .holds$0(group$holds$0),
        .holds$1(group$holds$1),
        .holds$2(group$holds$2),
        .holds$3(group$holds$3)
    );
    top$fetch$pos_y pos_y(
        .clock(pos_y$clock),
        .host_write(pos_y$host_write),
        .host_address(pos_y$host_address),
        .host_data(pos_y$host_data),
        .address(pos_y$address),
        .data(pos_y$data)
    );
    top$fetch$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1),
        .q$2(regs$q$2),
        .q$3(regs$q$3)
    );
    top$fetch$row_base_r row_base_r(
        .d(row_base_r$d),
        .q(row_base_r$q),
        .clock(row_base_r$clock)
    );
    top$fetch$schedule schedule(
        .clock(schedule$clock),
        .start(schedule$start),
        .writing(schedule$writing),
        .plane(schedule$plane),
        .chunk(schedule$chunk),
        .chunk_next(schedule$chunk_next),
        .period(schedule$period),
        .period_next(schedule$period_next),
        .write_buffer(schedule$write_buffer),
        .reading(schedule$reading),
        .ray(schedule$ray),
        .read_address(schedule$read_address),
        .cur_buffer(schedule$cur_buffer),
        .next_buffer(schedule$next_buffer),
        .host_write(schedule$host_write),
        .host_address(schedule$host_address),
        .host_data(schedule$host_data)
    );
    top$fetch$plane_r plane_r(
        .d(plane_r$d),
        .q(plane_r$q),
        .clock(plane_r$clock)
    );
    top$fetch$first_ray_r first_ray_r(
        .d(first_ray_r$d),
        .q(first_ray_r$q),
        .clock(first_ray_r$clock)
    );
    top$fetch$x_r$0 x_r$0(
        .d(x_r$0$d),
        .q(x_r$0$q),
        .clock(x_r$0$clock)
    );
    top$fetch$x_r$1 x_r$1(
        .d(x_r$1$d),
        .q(x_r$1$q),
        .clock(x_r$1$clock)
    );
    top$fetch$x_r$2 x_r$2(
        .d(x_r$2$d),
        .q(x_r$2$q),
        .clock(x_r$2$clock)
    );
    top$fetch$x_r$3 x_r$3(
        .d(x_r$3$d),
        .q(x_r$3$q),
        .clock(x_r$3$clock)
    );
    top$fetch$holds_r$0 holds_r$0(
        .d(holds_r$0$d),
        .q(holds_r$0$q),
        .clock(holds_r$0$clock)
    );
    top$fetch$holds_r$1 holds_r$1(
        .d(holds_r$1$d),
        .q(holds_r$1$q),
        .clock(holds_r$1$clock)
    );
    top$fetch$holds_r$2 holds_r$2(
        .d(holds_r$2$d),
        .q(holds_r$2$q),
        .clock(holds_r$2$clock)
    );
    top$fetch$holds_r$3 holds_r$3(
        .d(holds_r$3$d),
        .q(holds_r$3$q),
        .clock(holds_r$3$clock)
    );
    top$fetch$period_r period_r(
        .d(period_r$d),
        .q(period_r$q),
        .clock(period_r$clock)
    );
    top$fetch$writing_r writing_r(
        .d(writing_r$d),
        .q(writing_r$q),
        .clock(writing_r$clock)
    );
    top$fetch$buffer_r buffer_r(
        .d(buffer_r$d),
        .q(buffer_r$q),
        .clock(buffer_r$clock)
    );
    top$fetch$s1_row s1_row(
        .d(s1_row$d),
        .q(s1_row$q),
        .clock(s1_row$clock)
    );
    top$fetch$s1_plane s1_plane(
        .d(s1_plane$d),
        .q(s1_plane$q),
        .clock(s1_plane$clock)
    );
    top$fetch$s1_plane_offset s1_plane_offset(
        .d(s1_plane_offset$d),
        .q(s1_plane_offset$q),
        .clock(s1_plane_offset$clock)
    );
    top$fetch$s1_ray$0 s1_ray$0(
        .d(s1_ray$0$d),
        .q(s1_ray$0$q),
        .clock(s1_ray$0$clock)
    );
    top$fetch$s1_ray$1 s1_ray$1(
        .d(s1_ray$1$d),
        .q(s1_ray$1$q),
        .clock(s1_ray$1$clock)
    );
    top$fetch$s1_ray$2 s1_ray$2(
        .d(s1_ray$2$d),
        .q(s1_ray$2$q),
        .clock(s1_ray$2$clock)
    );
    top$fetch$s1_ray$3 s1_ray$3(
        .d(s1_ray$3$d),
        .q(s1_ray$3$q),
        .clock(s1_ray$3$clock)
    );
    top$fetch$s1_x$0 s1_x$0(
        .d(s1_x$0$d),
        .q(s1_x$0$q),
        .clock(s1_x$0$clock)
    );
    top$fetch$s1_x$1 s1_x$1(
        .d(s1_x$1$d),
        .q(s1_x$1$q),
        .clock(s1_x$1$clock)
    );
    top$fetch$s1_x$2 s1_x$2(
        .d(s1_x$2$d),
        .q(s1_x$2$q),
        .clock(s1_x$2$clock)
    );
    top$fetch$s1_x$3 s1_x$3(
        .d(s1_x$3$d),
        .q(s1_x$3$q),
        .clock(s1_x$3$clock)
    );
    top$fetch$s1_holds$0 s1_holds$0(
        .d(s1_holds$0$d),
        .q(s1_holds$0$q),
        .clock(s1_holds$0$clock)
    );
    top$fetch$s1_holds$1 s1_holds$1(
        .d(s1_holds$1$d),
        .q(s1_holds$1$q),
        .clock(s1_holds$1$clock)
    );
    top$fetch$s1_holds$2 s1_holds$2(
        .d(s1_holds$2$d),
        .q(s1_holds$2$q),
        .clock(s1_holds$2$clock)
    );
    top$fetch$s1_holds$3 s1_holds$3(
        .d(s1_holds$3$d),
        .q(s1_holds$3$q),
        .clock(s1_holds$3$clock)
    );
    top$fetch$s1_writing s1_writing(
        .d(s1_writing$d),
        .q(s1_writing$q),
        .clock(s1_writing$clock)
    );
    top$fetch$s1_buffer s1_buffer(
        .d(s1_buffer$d),
        .q(s1_buffer$q),
        .clock(s1_buffer$clock)
    );
    top$fetch$s2_inside$0 s2_inside$0(
        .d(s2_inside$0$d),
        .q(s2_inside$0$q),
        .clock(s2_inside$0$clock)
    );
    top$fetch$s2_inside$1 s2_inside$1(
        .d(s2_inside$1$d),
        .q(s2_inside$1$q),
        .clock(s2_inside$1$clock)
    );
    top$fetch$s2_inside$2 s2_inside$2(
        .d(s2_inside$2$d),
        .q(s2_inside$2$q),
        .clock(s2_inside$2$clock)
    );
    top$fetch$s2_inside$3 s2_inside$3(
        .d(s2_inside$3$d),
        .q(s2_inside$3$q),
        .clock(s2_inside$3$clock)
    );
    top$fetch$s2_module$0 s2_module$0(
        .d(s2_module$0$d),
        .q(s2_module$0$q),
        .clock(s2_module$0$clock)
    );
    top$fetch$s2_module$1 s2_module$1(
        .d(s2_module$1$d),
        .q(s2_module$1$q),
        .clock(s2_module$1$clock)
    );
    top$fetch$s2_module$2 s2_module$2(
        .d(s2_module$2$d),
        .q(s2_module$2$q),
        .clock(s2_module$2$clock)
    );
    top$fetch$s2_module$3 s2_module$3(
        .d(s2_module$3$d),
        .q(s2_module$3$q),
        .clock(s2_module$3$clock)
    );
    top$fetch$s2_address$0 s2_address$0(
        .d(s2_address$0$d),
        .q(s2_address$0$q),
        .clock(s2_address$0$clock)
    );
    top$fetch$s2_address$1 s2_address$1(
        .d(s2_address$1$d),
        .q(s2_address$1$q),
        .clock(s2_address$1$clock)
    );
    top$fetch$s2_address$2 s2_address$2(
        .d(s2_address$2$d),
        .q(s2_address$2$q),
        .clock(s2_address$2$clock)
    );
    top$fetch$s2_address$3 s2_address$3(
        .d(s2_address$3$d),
        .q(s2_address$3$q),
        .clock(s2_address$3$clock)
    );
    top$fetch$s2_holds$0 s2_holds$0(
        .d(s2_holds$0$d),
        .q(s2_holds$0$q),
        .clock(s2_holds$0$clock)
    );
    top$fetch$s2_holds$1 s2_holds$1(
        .d(s2_holds$1$d),
        .q(s2_holds$1$q),
        .clock(s2_holds$1$clock)
    );
    top$fetch$s2_holds$2 s2_holds$2(
        .d(s2_holds$2$d),
        .q(s2_holds$2$q),
        .clock(s2_holds$2$clock)
    );
    top$fetch$s2_holds$3 s2_holds$3(
        .d(s2_holds$3$d),
        .q(s2_holds$3$q),
        .clock(s2_holds$3$clock)
    );
    top$fetch$s2_dsb$0 s2_dsb$0(
        .d(s2_dsb$0$d),
        .q(s2_dsb$0$q),
        .clock(s2_dsb$0$clock)
    );
    top$fetch$s2_dsb$1 s2_dsb$1(
        .d(s2_dsb$1$d),
        .q(s2_dsb$1$q),
        .clock(s2_dsb$1$clock)
    );
    top$fetch$s2_dsb$2 s2_dsb$2(
        .d(s2_dsb$2$d),
        .q(s2_dsb$2$q),
        .clock(s2_dsb$2$clock)
    );
    top$fetch$s2_dsb$3 s2_dsb$3(
        .d(s2_dsb$3$d),
        .q(s2_dsb$3$q),
        .clock(s2_dsb$3$clock)
    );
    top$fetch$s2_write_address$0 s2_write_address$0(
        .d(s2_write_address$0$d),
        .q(s2_write_address$0$q),
        .clock(s2_write_address$0$clock)
    );
    top$fetch$s2_write_address$1 s2_write_address$1(
        .d(s2_write_address$1$d),
        .q(s2_write_address$1$q),
        .clock(s2_write_address$1$clock)
    );
    top$fetch$s2_write_address$2 s2_write_address$2(
        .d(s2_write_address$2$d),
        .q(s2_write_address$2$q),
        .clock(s2_write_address$2$clock)
    );
    top$fetch$s2_write_address$3 s2_write_address$3(
        .d(s2_write_address$3$d),
        .q(s2_write_address$3$q),
        .clock(s2_write_address$3$clock)
    );
    top$fetch$s2_in_stream$0 s2_in_stream$0(
        .d(s2_in_stream$0$d),
        .q(s2_in_stream$0$q),
        .clock(s2_in_stream$0$clock)
    );
    top$fetch$s2_in_stream$1 s2_in_stream$1(
        .d(s2_in_stream$1$d),
        .q(s2_in_stream$1$q),
        .clock(s2_in_stream$1$clock)
    );
    top$fetch$s2_in_stream$2 s2_in_stream$2(
        .d(s2_in_stream$2$d),
        .q(s2_in_stream$2$q),
        .clock(s2_in_stream$2$clock)
    );
    top$fetch$s2_in_stream$3 s2_in_stream$3(
        .d(s2_in_stream$3$d),
        .q(s2_in_stream$3$q),
        .clock(s2_in_stream$3$clock)
    );
    top$fetch$s2_writing s2_writing(
        .d(s2_writing$d),
        .q(s2_writing$q),
        .clock(s2_writing$clock)
    );
    top$fetch$s2_buffer s2_buffer(
        .d(s2_buffer$d),
        .q(s2_buffer$q),
        .clock(s2_buffer$clock)
    );
    top$fetch$holds_q$0 holds_q$0(
        .d(holds_q$0$d),
        .q(holds_q$0$q),
        .clock(holds_q$0$clock)
    );
    top$fetch$holds_q$1 holds_q$1(
        .d(holds_q$1$d),
        .q(holds_q$1$q),
        .clock(holds_q$1$clock)
    );
    top$fetch$holds_q$2 holds_q$2(
        .d(holds_q$2$d),
        .q(holds_q$2$q),
        .clock(holds_q$2$clock)
    );
    top$fetch$holds_q$3 holds_q$3(
        .d(holds_q$3$d),
        .q(holds_q$3$q),
        .clock(holds_q$3$clock)
    );
    top$fetch$inside_q$0 inside_q$0(
        .d(inside_q$0$d),
        .q(inside_q$0$q),
        .clock(inside_q$0$clock)
    );
    top$fetch$inside_q$1 inside_q$1(
        .d(inside_q$1$d),
        .q(inside_q$1$q),
        .clock(inside_q$1$clock)
    );
    top$fetch$inside_q$2 inside_q$2(
        .d(inside_q$2$d),
        .q(inside_q$2$q),
        .clock(inside_q$2$clock)
    );
    top$fetch$inside_q$3 inside_q$3(
        .d(inside_q$3$d),
        .q(inside_q$3$q),
        .clock(inside_q$3$clock)
    );
    top$fetch$module_q$0 module_q$0(
        .d(module_q$0$d),
        .q(module_q$0$q),
        .clock(module_q$0$clock)
    );
    top$fetch$module_q$1 module_q$1(
        .d(module_q$1$d),
        .q(module_q$1$q),
        .clock(module_q$1$clock)
    );
    top$fetch$module_q$2 module_q$2(
        .d(module_q$2$d),
        .q(module_q$2$q),
        .clock(module_q$2$clock)
    );
    top$fetch$module_q$3 module_q$3(
        .d(module_q$3$d),
        .q(module_q$3$q),
        .clock(module_q$3$clock)
    );
    top$fetch$dsb_q$0 dsb_q$0(
        .d(dsb_q$0$d),
        .q(dsb_q$0$q),
        .clock(dsb_q$0$clock)
    );
    top$fetch$dsb_q$1 dsb_q$1(
        .d(dsb_q$1$d),
        .q(dsb_q$1$q),
        .clock(dsb_q$1$clock)
    );
    top$fetch$dsb_q$2 dsb_q$2(
        .d(dsb_q$2$d),
        .q(dsb_q$2$q),
        .clock(dsb_q$2$clock)
    );
    top$fetch$dsb_q$3 dsb_q$3(
        .d(dsb_q$3$d),
        .q(dsb_q$3$q),
        .clock(dsb_q$3$clock)
    );
    top$fetch$write_address_q$0 write_address_q$0(
        .d(write_address_q$0$d),
        .q(write_address_q$0$q),
        .clock(write_address_q$0$clock)
    );
    top$fetch$write_address_q$1 write_address_q$1(
        .d(write_address_q$1$d),
        .q(write_address_q$1$q),
        .clock(write_address_q$1$clock)
    );
    top$fetch$write_address_q$2 write_address_q$2(
        .d(write_address_q$2$d),
        .q(write_address_q$2$q),
        .clock(write_address_q$2$clock)
    );
    top$fetch$write_address_q$3 write_address_q$3(
        .d(write_address_q$3$d),
        .q(write_address_q$3$q),
        .clock(write_address_q$3$clock)
    );
    top$fetch$in_stream_q$0 in_stream_q$0(
        .d(in_stream_q$0$d),
        .q(in_stream_q$0$q),
        .clock(in_stream_q$0$clock)
    );
    top$fetch$in_stream_q$1 in_stream_q$1(
        .d(in_stream_q$1$d),
        .q(in_stream_q$1$q),
        .clock(in_stream_q$1$clock)
    );
    top$fetch$in_stream_q$2 in_stream_q$2(
        .d(in_stream_q$2$d),
        .q(in_stream_q$2$q),
        .clock(in_stream_q$2$clock)
    );
    top$fetch$in_stream_q$3 in_stream_q$3(
        .d(in_stream_q$3$d),
        .q(in_stream_q$3$q),
        .clock(in_stream_q$3$clock)
    );
    top$fetch$write_q write_q(
        .d(write_q$d),
        .q(write_q$q),
        .clock(write_q$clock)
    );
    top$fetch$buffer_q buffer_q(
        .d(buffer_q$d),
        .q(buffer_q$q),
        .clock(buffer_q$clock)
    );
    top$fetch$read_q read_q(
        .d(read_q$d),
        .q(read_q$q),
        .clock(read_q$clock)
    );
    top$fetch$lane_q lane_q(
        .d(lane_q$d),
        .q(lane_q$q),
        .clock(lane_q$clock)
    );
    top$fetch$cur_q cur_q(
        .d(cur_q$d),
        .q(cur_q$q),
        .clock(cur_q$clock)
    );
    top$fetch$next_q next_q(
        .d(next_q$d),
        .q(next_q$q),
        .clock(next_q$clock)
    );
    top$fetch$cur_m$0 cur_m$0(
        .d(cur_m$0$d),
        .q(cur_m$0$q),
        .clock(cur_m$0$clock)
    );
    top$fetch$cur_m$1 cur_m$1(
        .d(cur_m$1$d),
        .q(cur_m$1$q),
        .clock(cur_m$1$clock)
    );
    top$fetch$cur_m$2 cur_m$2(
        .d(cur_m$2$d),
        .q(cur_m$2$q),
        .clock(cur_m$2$clock)
    );
    top$fetch$cur_m$3 cur_m$3(
        .d(cur_m$3$d),
        .q(cur_m$3$q),
        .clock(cur_m$3$clock)
    );
    top$fetch$next_m$0 next_m$0(
        .d(next_m$0$d),
        .q(next_m$0$q),
        .clock(next_m$0$clock)
    );
    top$fetch$next_m$1 next_m$1(
        .d(next_m$1$d),
        .q(next_m$1$q),
        .clock(next_m$1$clock)
    );
    top$fetch$next_m$2 next_m$2(
        .d(next_m$2$d),
        .q(next_m$2$q),
        .clock(next_m$2$clock)
    );
    top$fetch$next_m$3 next_m$3(
        .d(next_m$3$d),
        .q(next_m$3$q),
        .clock(next_m$3$clock)
    );
    top$fetch$read_q2 read_q2(
        .d(read_q2$d),
        .q(read_q2$q),
        .clock(read_q2$clock)
    );
    top$fetch$lane_q2 lane_q2(
        .d(lane_q2$d),
        .q(lane_q2$q),
        .clock(lane_q2$clock)
    );
    
    // Update code
    reg  [15:0] cur$0_pass;
    reg  [15:0] cur$1_pass;
    reg  [15:0] cur$2_pass;
    reg  [15:0] cur$3_pass;
    reg  [15:0] next$0_pass;
    reg  [15:0] next$1_pass;
    reg  [15:0] next$2_pass;
    reg  [15:0] next$3_pass;
    reg  [31:0] ext_addr$0_pass;
    reg  [31:0] ext_addr$1_pass;
    reg  [31:0] ext_addr$2_pass;
    reg  [31:0] ext_addr$3_pass;
    always @(*) begin
        plane_r$clock = clock;
        first_ray_r$clock = clock;
        period_r$clock = clock;
        writing_r$clock = clock;
        buffer_r$clock = clock;
        row_base_r$clock = clock;
        s1_row$clock = clock;
        s1_plane$clock = clock;
        s1_plane_offset$clock = clock;
        s1_writing$clock = clock;
        s1_buffer$clock = clock;
        s2_writing$clock = clock;
        s2_buffer$clock = clock;
        write_q$clock = clock;
        buffer_q$clock = clock;
        read_q$clock = clock;
        lane_q$clock = clock;
        cur_q$clock = clock;
        next_q$clock = clock;
        read_q2$clock = clock;
        lane_q2$clock = clock;
        plane_r$d = plane_r$q;
        first_ray_r$d = first_ray_r$q;
        period_r$d = period_r$q;
        writing_r$d = writing_r$q;
        buffer_r$d = buffer_r$q;
        row_base_r$d = row_base_r$q;
        s1_row$d = s1_row$q;
        s1_plane$d = s1_plane$q;
        s1_plane_offset$d = s1_plane_offset$q;
        s1_writing$d = s1_writing$q;
        s1_buffer$d = s1_buffer$q;
        s2_writing$d = s2_writing$q;
        s2_buffer$d = s2_buffer$q;
        write_q$d = write_q$q;
        buffer_q$d = buffer_q$q;
        read_q$d = read_q$q;
        lane_q$d = lane_q$q;
        cur_q$d = cur_q$q;
        next_q$d = next_q$q;
        read_q2$d = read_q2$q;
        lane_q2$d = lane_q2$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        rays = regs$q$0[('h0)+:(16)];
        segments = regs$q$0[('h20)+:(16)];
        n_x = regs$q$1[('h0)+:(16)];
        n_y = regs$q$1[('h10)+:(16)];
        n_k = regs$q$1[('h20)+:(16)];
        row_words = regs$q$2[('h0)+:(16)];
        plane_words = regs$q$2[('h10)+:(16)];
        row_stride = 'h0;
        if (perspective) begin
            row_stride = regs$q$2[('h20)+:(16)];
        end
        v0 = regs$q$3[('h10)+:(16)];
        pos_y$clock = clock;
        pos_y$host_write = host_write;
        pos_y$host_address = host_address;
        pos_y$host_data = host_data;
        group$clock = clock;
        group$host_write = host_write;
        group$host_address = host_address;
        group$host_data = host_data;
        group$u0 = regs$q$3[('h0)+:(16)];
        schedule$clock = clock;
        schedule$start = start;
        schedule$host_write = host_write;
        schedule$host_address = host_address;
        schedule$host_data = host_data;
        group$chunk = schedule$chunk;
        group$chunk_next = schedule$chunk_next;
        group$plane_count = schedule$plane;
        row_base_r$d = schedule$period_next * row_stride;
        row_entry = row_base_r$q + 32'(group$plane);
        pos_y$address = row_entry[('h0)+:(18)];
        plane_r$d = group$plane;
        first_ray_r$d = group$first_ray;
        period_r$d = schedule$period;
        writing_r$d = schedule$writing;
        buffer_r$d = schedule$write_buffer;
        s1_row$d = v0 + period_r$q + pos_y$data;
        s1_plane$d = plane_r$q;
        s1_plane_offset$d = plane_r$q * plane_words;
        s1_plane_segment = s1_plane$q >> shift;
        s1_writing$d = writing_r$q;
        s1_buffer$d = buffer_r$q;
        s2_writing$d = s1_writing$q;
        s2_buffer$d = s1_buffer$q;
        write_q$d = s2_writing$q;
        buffer_q$d = s2_buffer$q;
        x_r$0$clock = clock;
        holds_r$0$clock = clock;
        s1_ray$0$clock = clock;
        s1_x$0$clock = clock;
        s1_holds$0$clock = clock;
        s2_inside$0$clock = clock;
        s2_module$0$clock = clock;
        s2_address$0$clock = clock;
        s2_holds$0$clock = clock;
        s2_dsb$0$clock = clock;
        s2_write_address$0$clock = clock;
        s2_in_stream$0$clock = clock;
        holds_q$0$clock = clock;
        inside_q$0$clock = clock;
        module_q$0$clock = clock;
        dsb_q$0$clock = clock;
        write_address_q$0$clock = clock;
        in_stream_q$0$clock = clock;
        x_r$0$d = group$x$0;
        holds_r$0$d = group$holds$0;
        s1_ray$0$d = first_ray_r$q + index$0;
        s1_x$0$d = x_r$0$q;
        s1_holds$0$d = holds_r$0$q;
        lane_inside$0 = s1_holds$0$q & ~s1_x$0$q['hf] & (s1_x$0$q < n_x) & ~s1_row$q['hf] & (s1_row$q < n_y) & (s1_plane$q < n_k);
        lane_module$0 = (s1_x$0$q + s1_row$q + s1_plane$q) & mask;
        lane_column$0 = s1_x$0$q >> shift;
        lane_address$0 = lane_column$0 * one + s1_row$q * row_words + s1_plane_offset$q;
        lane_dsb$0 = (s1_ray$0$q + s1_plane$q) & mask;
        lane_write_address$0 = s1_ray$0$q * segments + 32'(s1_plane_segment);
        s2_inside$0$d = lane_inside$0;
        s2_module$0$d = lane_module$0;
        s2_address$0$d = lane_address$0;
        s2_holds$0$d = s1_holds$0$q;
        s2_dsb$0$d = lane_dsb$0;
        s2_write_address$0$d = lane_write_address$0;
        s2_in_stream$0$d = s1_ray$0$q < rays;
        holds_q$0$d = s2_holds$0$q;
        inside_q$0$d = s2_inside$0$q;
        module_q$0$d = s2_module$0$q;
        dsb_q$0$d = s2_dsb$0$q;
        write_address_q$0$d = s2_write_address$0$q;
        in_stream_q$0$d = s2_in_stream$0$q;
        x_r$1$clock = clock;
        holds_r$1$clock = clock;
        s1_ray$1$clock = clock;
        s1_x$1$clock = clock;
        s1_holds$1$clock = clock;
        s2_inside$1$clock = clock;
        s2_module$1$clock = clock;
        s2_address$1$clock = clock;
        s2_holds$1$clock = clock;
        s2_dsb$1$clock = clock;
        s2_write_address$1$clock = clock;
        s2_in_stream$1$clock = clock;
        holds_q$1$clock = clock;
        inside_q$1$clock = clock;
        module_q$1$clock = clock;
        dsb_q$1$clock = clock;
        write_address_q$1$clock = clock;
        in_stream_q$1$clock = clock;
        x_r$1$d = group$x$1;
        holds_r$1$d = group$holds$1;
        s1_ray$1$d = first_ray_r$q + index$1;
        s1_x$1$d = x_r$1$q;
        s1_holds$1$d = holds_r$1$q;
        lane_inside$1 = s1_holds$1$q & ~s1_x$1$q['hf] & (s1_x$1$q < n_x) & ~s1_row$q['hf] & (s1_row$q < n_y) & (s1_plane$q < n_k);
        lane_module$1 = (s1_x$1$q + s1_row$q + s1_plane$q) & mask;
        lane_column$1 = s1_x$1$q >> shift;
        lane_address$1 = lane_column$1 * one + s1_row$q * row_words + s1_plane_offset$q;
        lane_dsb$1 = (s1_ray$1$q + s1_plane$q) & mask;
        lane_write_address$1 = s1_ray$1$q * segments + 32'(s1_plane_segment);
        s2_inside$1$d = lane_inside$1;
        s2_module$1$d = lane_module$1;
        s2_address$1$d = lane_address$1;
        s2_holds$1$d = s1_holds$1$q;
        s2_dsb$1$d = lane_dsb$1;
        s2_write_address$1$d = lane_write_address$1;
        s2_in_stream$1$d = s1_ray$1$q < rays;
        holds_q$1$d = s2_holds$1$q;
        inside_q$1$d = s2_inside$1$q;
        module_q$1$d = s2_module$1$q;
        dsb_q$1$d = s2_dsb$1$q;
        write_address_q$1$d = s2_write_address$1$q;
        in_stream_q$1$d = s2_in_stream$1$q;
        x_r$2$clock = clock;
        holds_r$2$clock = clock;
        s1_ray$2$clock = clock;
        s1_x$2$clock = clock;
        s1_holds$2$clock = clock;
        s2_inside$2$clock = clock;
        s2_module$2$clock = clock;
        s2_address$2$clock = clock;
        s2_holds$2$clock = clock;
        s2_dsb$2$clock = clock;
        s2_write_address$2$clock = clock;
        s2_in_stream$2$clock = clock;
        holds_q$2$clock = clock;
        inside_q$2$clock = clock;
        module_q$2$clock = clock;
        dsb_q$2$clock = clock;
        write_address_q$2$clock = clock;
        in_stream_q$2$clock = clock;
        x_r$2$d = group$x$2;
        holds_r$2$d = group$holds$2;
        s1_ray$2$d = first_ray_r$q + index$2;
        s1_x$2$d = x_r$2$q;
        s1_holds$2$d = holds_r$2$q;
        lane_inside$2 = s1_holds$2$q & ~s1_x$2$q['hf] & (s1_x$2$q < n_x) & ~s1_row$q['hf] & (s1_row$q < n_y) & (s1_plane$q < n_k);
        lane_module$2 = (s1_x$2$q + s1_row$q + s1_plane$q) & mask;
        lane_column$2 = s1_x$2$q >> shift;
        lane_address$2 = lane_column$2 * one + s1_row$q * row_words + s1_plane_offset$q;
        lane_dsb$2 = (s1_ray$2$q + s1_plane$q) & mask;
        lane_write_address$2 = s1_ray$2$q * segments + 32'(s1_plane_segment);
        s2_inside$2$d = lane_inside$2;
        s2_module$2$d = lane_module$2;
        s2_address$2$d = lane_address$2;
        s2_holds$2$d = s1_holds$2$q;
        s2_dsb$2$d = lane_dsb$2;
        s2_write_address$2$d = lane_write_address$2;
        s2_in_stream$2$d = s1_ray$2$q < rays;
        holds_q$2$d = s2_holds$2$q;
        inside_q$2$d = s2_inside$2$q;
        module_q$2$d = s2_module$2$q;
        dsb_q$2$d = s2_dsb$2$q;
        write_address_q$2$d = s2_write_address$2$q;
        in_stream_q$2$d = s2_in_stream$2$q;
        x_r$3$clock = clock;
        holds_r$3$clock = clock;
        s1_ray$3$clock = clock;
        s1_x$3$clock = clock;
        s1_holds$3$clock = clock;
        s2_inside$3$clock = clock;
        s2_module$3$clock = clock;
        s2_address$3$clock = clock;
        s2_holds$3$clock = clock;
        s2_dsb$3$clock = clock;
        s2_write_address$3$clock = clock;
        s2_in_stream$3$clock = clock;
        holds_q$3$clock = clock;
        inside_q$3$clock = clock;
        module_q$3$clock = clock;
        dsb_q$3$clock = clock;
        write_address_q$3$clock = clock;
        in_stream_q$3$clock = clock;
        x_r$3$d = group$x$3;
        holds_r$3$d = group$holds$3;
        s1_ray$3$d = first_ray_r$q + index$3;
        s1_x$3$d = x_r$3$q;
        s1_holds$3$d = holds_r$3$q;
        lane_inside$3 = s1_holds$3$q & ~s1_x$3$q['hf] & (s1_x$3$q < n_x) & ~s1_row$q['hf] & (s1_row$q < n_y) & (s1_plane$q < n_k);
        lane_module$3 = (s1_x$3$q + s1_row$q + s1_plane$q) & mask;
        lane_column$3 = s1_x$3$q >> shift;
        lane_address$3 = lane_column$3 * one + s1_row$q * row_words + s1_plane_offset$q;
        lane_dsb$3 = (s1_ray$3$q + s1_plane$q) & mask;
        lane_write_address$3 = s1_ray$3$q * segments + 32'(s1_plane_segment);
        s2_inside$3$d = lane_inside$3;
        s2_module$3$d = lane_module$3;
        s2_address$3$d = lane_address$3;
        s2_holds$3$d = s1_holds$3$q;
        s2_dsb$3$d = lane_dsb$3;
        s2_write_address$3$d = lane_write_address$3;
        s2_in_stream$3$d = s1_ray$3$q < rays;
        holds_q$3$d = s2_holds$3$q;
        inside_q$3$d = s2_inside$3$q;
        module_q$3$d = s2_module$3$q;
        dsb_q$3$d = s2_dsb$3$q;
        write_address_q$3$d = s2_write_address$3$q;
        in_stream_q$3$d = s2_in_stream$3$q;
        address$0 = 'h0;
        reads$0 = 1'b0;
        if (s2_inside$0$q & (s2_module$0$q == index$0)) begin
            address$0 = s2_address$0$q;
            reads$0 = 1'b1;
        end
        if (s2_inside$1$q & (s2_module$1$q == index$0)) begin
            address$0 = s2_address$1$q;
            reads$0 = 1'b1;
        end
        if (s2_inside$2$q & (s2_module$2$q == index$0)) begin
            address$0 = s2_address$2$q;
            reads$0 = 1'b1;
        end
        if (s2_inside$3$q & (s2_module$3$q == index$0)) begin
            address$0 = s2_address$3$q;
            reads$0 = 1'b1;
        end
        memory$0$read_clock = clock;
        memory$0$write_clock = clock;
        memory$0$write_enable = load_enable & (load_module == module_id$0) & ~external;
        memory$0$write_address = load_address[('h0)+:(16)];
        memory$0$write_data = load_data;
        memory$0$read_address = 'h0;
        ext_addr$0_pass = 'h0;
        if (reads$0 & ~external) begin
            memory$0$read_address = address$0[('h0)+:(16)];
        end
        if (reads$0 & external) begin
            ext_addr$0_pass = address$0;
        end
        word$0 = memory$0$read_data;
        if (external) begin
            word$0 = ext_data$0;
        end
        address$1 = 'h0;
        reads$1 = 1'b0;
        if (s2_inside$0$q & (s2_module$0$q == index$1)) begin
            address$1 = s2_address$0$q;
            reads$1 = 1'b1;
        end
        if (s2_inside$1$q & (s2_module$1$q == index$1)) begin
            address$1 = s2_address$1$q;
            reads$1 = 1'b1;
        end
        if (s2_inside$2$q & (s2_module$2$q == index$1)) begin
            address$1 = s2_address$2$q;
            reads$1 = 1'b1;
        end
        if (s2_inside$3$q & (s2_module$3$q == index$1)) begin
            address$1 = s2_address$3$q;
            reads$1 = 1'b1;
        end
        memory$1$read_clock = clock;
        memory$1$write_clock = clock;
        memory$1$write_enable = load_enable & (load_module == module_id$1) & ~external;
        memory$1$write_address = load_address[('h0)+:(16)];
        memory$1$write_data = load_data;
        memory$1$read_address = 'h0;
        ext_addr$1_pass = 'h0;
        if (reads$1 & ~external) begin
            memory$1$read_address = address$1[('h0)+:(16)];
        end
        if (reads$1 & external) begin
            ext_addr$1_pass = address$1;
        end
        word$1 = memory$1$read_data;
        if (external) begin
            word$1 = ext_data$1;
        end
        address$2 = 'h0;
        reads$2 = 1'b0;
        if (s2_inside$0$q & (s2_module$0$q == index$2)) begin
            address$2 = s2_address$0$q;
            reads$2 = 1'b1;
        end
        if (s2_inside$1$q & (s2_module$1$q == index$2)) begin
            address$2 = s2_address$1$q;
            reads$2 = 1'b1;
        end
        if (s2_inside$2$q & (s2_module$2$q == index$2)) begin
            address$2 = s2_address$2$q;
            reads$2 = 1'b1;
        end
        if (s2_inside$3$q & (s2_module$3$q == index$2)) begin
            address$2 = s2_address$3$q;
            reads$2 = 1'b1;
        end
        memory$2$read_clock = clock;
        memory$2$write_clock = clock;
        memory$2$write_enable = load_enable & (load_module == module_id$2) & ~external;
        memory$2$write_address = load_address[('h0)+:(16)];
        memory$2$write_data = load_data;
        memory$2$read_address = 'h0;
        ext_addr$2_pass = 'h0;
        if (reads$2 & ~external) begin
            memory$2$read_address = address$2[('h0)+:(16)];
        end
        if (reads$2 & external) begin
            ext_addr$2_pass = address$2;
        end
        word$2 = memory$2$read_data;
        if (external) begin
            word$2 = ext_data$2;
        end
        address$3 = 'h0;
        reads$3 = 1'b0;
        if (s2_inside$0$q & (s2_module$0$q == index$3)) begin
            address$3 = s2_address$0$q;
            reads$3 = 1'b1;
        end
        if (s2_inside$1$q & (s2_module$1$q == index$3)) begin
            address$3 = s2_address$1$q;
            reads$3 = 1'b1;
        end
        if (s2_inside$2$q & (s2_module$2$q == index$3)) begin
            address$3 = s2_address$2$q;
            reads$3 = 1'b1;
        end
        if (s2_inside$3$q & (s2_module$3$q == index$3)) begin
            address$3 = s2_address$3$q;
            reads$3 = 1'b1;
        end
        memory$3$read_clock = clock;
        memory$3$write_clock = clock;
        memory$3$write_enable = load_enable & (load_module == module_id$3) & ~external;
        memory$3$write_address = load_address[('h0)+:(16)];
        memory$3$write_data = load_data;
        memory$3$read_address = 'h0;
        ext_addr$3_pass = 'h0;
        if (reads$3 & ~external) begin
            memory$3$read_address = address$3[('h0)+:(16)];
        end
        if (reads$3 & external) begin
            ext_addr$3_pass = address$3;
        end
        word$3 = memory$3$read_data;
        if (external) begin
            word$3 = ext_data$3;
        end
        value$0 = 'h0;
        if (inside_q$0$q & (module_q$0$q == index$0)) begin
            value$0 = word$0;
        end
        if (inside_q$0$q & (module_q$0$q == index$1)) begin
            value$0 = word$1;
        end
        if (inside_q$0$q & (module_q$0$q == index$2)) begin
            value$0 = word$2;
        end
        if (inside_q$0$q & (module_q$0$q == index$3)) begin
            value$0 = word$3;
        end
        value$1 = 'h0;
        if (inside_q$1$q & (module_q$1$q == index$0)) begin
            value$1 = word$0;
        end
        if (inside_q$1$q & (module_q$1$q == index$1)) begin
            value$1 = word$1;
        end
        if (inside_q$1$q & (module_q$1$q == index$2)) begin
            value$1 = word$2;
        end
        if (inside_q$1$q & (module_q$1$q == index$3)) begin
            value$1 = word$3;
        end
        value$2 = 'h0;
        if (inside_q$2$q & (module_q$2$q == index$0)) begin
            value$2 = word$0;
        end
        if (inside_q$2$q & (module_q$2$q == index$1)) begin
            value$2 = word$1;
        end
        if (inside_q$2$q & (module_q$2$q == index$2)) begin
            value$2 = word$2;
        end
        if (inside_q$2$q & (module_q$2$q == index$3)) begin
            value$2 = word$3;
        end
        value$3 = 'h0;
        if (inside_q$3$q & (module_q$3$q == index$0)) begin
            value$3 = word$0;
        end
        if (inside_q$3$q & (module_q$3$q == index$1)) begin
            value$3 = word$1;
        end
        if (inside_q$3$q & (module_q$3$q == index$2)) begin
            value$3 = word$2;
        end
        if (inside_q$3$q & (module_q$3$q == index$3)) begin
            value$3 = word$3;
        end
        dsb_data$0 = 'h0;
        write_address$0 = 'h0;
        dsb_write$0 = 1'b0;
        if (holds_q$0$q & (dsb_q$0$q == index$0)) begin
            dsb_data$0 = value$0;
            write_address$0 = write_address_q$0$q;
            dsb_write$0 = in_stream_q$0$q;
        end
        if (holds_q$1$q & (dsb_q$1$q == index$0)) begin
            dsb_data$0 = value$1;
            write_address$0 = write_address_q$1$q;
            dsb_write$0 = in_stream_q$1$q;
        end
        if (holds_q$2$q & (dsb_q$2$q == index$0)) begin
            dsb_data$0 = value$2;
            write_address$0 = write_address_q$2$q;
            dsb_write$0 = in_stream_q$2$q;
        end
        if (holds_q$3$q & (dsb_q$3$q == index$0)) begin
            dsb_data$0 = value$3;
            write_address$0 = write_address_q$3$q;
            dsb_write$0 = in_stream_q$3$q;
        end
        buffer0$0$write_clock = clock;
        buffer1$0$write_clock = clock;
        buffer2$0$write_clock = clock;
        buffer0$0$write_address = write_address$0[('h0)+:(17)];
        buffer1$0$write_address = write_address$0[('h0)+:(17)];
        buffer2$0$write_address = write_address$0[('h0)+:(17)];
        buffer0$0$write_data = dsb_data$0;
        buffer1$0$write_data = dsb_data$0;
        buffer2$0$write_data = dsb_data$0;
        buffer0$0$write_enable = write_q$q & dsb_write$0 & (buffer_q$q == buffer_id$0);
        buffer1$0$write_enable = write_q$q & dsb_write$0 & (buffer_q$q == buffer_id$1);
        buffer2$0$write_enable = write_q$q & dsb_write$0 & (buffer_q$q == buffer_id$2);
        dsb_data$1 = 'h0;
        write_address$1 = 'h0;
        dsb_write$1 = 1'b0;
        if (holds_q$0$q & (dsb_q$0$q == index$1)) begin
            dsb_data$1 = value$0;
            write_address$1 = write_address_q$0$q;
            dsb_write$1 = in_stream_q$0$q;
        end
        if (holds_q$1$q & (dsb_q$1$q == index$1)) begin
            dsb_data$1 = value$1;
            write_address$1 = write_address_q$1$q;
            dsb_write$1 = in_stream_q$1$q;
        end
        if (holds_q$2$q & (dsb_q$2$q == index$1)) begin
            dsb_data$1 = value$2;
            write_address$1 = write_address_q$2$q;
            dsb_write$1 = in_stream_q$2$q;
        end
        if (holds_q$3$q & (dsb_q$3$q == index$1)) begin
            dsb_data$1 = value$3;
            write_address$1 = write_address_q$3$q;
            dsb_write$1 = in_stream_q$3$q;
        end
        buffer0$1$write_clock = clock;
        buffer1$1$write_clock = clock;
        buffer2$1$write_clock = clock;
        buffer0$1$write_address = write_address$1[('h0)+:(17)];
        buffer1$1$write_address = write_address$1[('h0)+:(17)];
        buffer2$1$write_address = write_address$1[('h0)+:(17)];
        buffer0$1$write_data = dsb_data$1;
        buffer1$1$write_data = dsb_data$1;
        buffer2$1$write_data = dsb_data$1;
        buffer0$1$write_enable = write_q$q & dsb_write$1 & (buffer_q$q == buffer_id$0);
        buffer1$1$write_enable = write_q$q & dsb_write$1 & (buffer_q$q == buffer_id$1);
        buffer2$1$write_enable = write_q$q & dsb_write$1 & (buffer_q$q == buffer_id$2);
        dsb_data$2 = 'h0;
        write_address$2 = 'h0;
        dsb_write$2 = 1'b0;
        if (holds_q$0$q & (dsb_q$0$q == index$2)) begin
            dsb_data$2 = value$0;
            write_address$2 = write_address_q$0$q;
            dsb_write$2 = in_stream_q$0$q;
        end
        if (holds_q$1$q & (dsb_q$1$q == index$2)) begin
            dsb_data$2 = value$1;
            write_address$2 = write_address_q$1$q;
            dsb_write$2 = in_stream_q$1$q;
        end
        if (holds_q$2$q & (dsb_q$2$q == index$2)) begin
            dsb_data$2 = value$2;
            write_address$2 = write_address_q$2$q;
            dsb_write$2 = in_stream_q$2$q;
        end
        if (holds_q$3$q & (dsb_q$3$q == index$2)) begin
            dsb_data$2 = value$3;
            write_address$2 = write_address_q$3$q;
            dsb_write$2 = in_stream_q$3$q;
        end
        buffer0$2$write_clock = clock;
        buffer1$2$write_clock = clock;
        buffer2$2$write_clock = clock;
        buffer0$2$write_address = write_address$2[('h0)+:(17)];
        buffer1$2$write_address = write_address$2[('h0)+:(17)];
        buffer2$2$write_address = write_address$2[('h0)+:(17)];
        buffer0$2$write_data = dsb_data$2;
        buffer1$2$write_data = dsb_data$2;
        buffer2$2$write_data = dsb_data$2;
        buffer0$2$write_enable = write_q$q & dsb_write$2 & (buffer_q$q == buffer_id$0);
        buffer1$2$write_enable = write_q$q & dsb_write$2 & (buffer_q$q == buffer_id$1);
        buffer2$2$write_enable = write_q$q & dsb_write$2 & (buffer_q$q == buffer_id$2);
        dsb_data$3 = 'h0;
        write_address$3 = 'h0;
        dsb_write$3 = 1'b0;
        if (holds_q$0$q & (dsb_q$0$q == index$3)) begin
            dsb_data$3 = value$0;
            write_address$3 = write_address_q$0$q;
            dsb_write$3 = in_stream_q$0$q;
        end
        if (holds_q$1$q & (dsb_q$1$q == index$3)) begin
            dsb_data$3 = value$1;
            write_address$3 = write_address_q$1$q;
            dsb_write$3 = in_stream_q$1$q;
        end
        if (holds_q$2$q & (dsb_q$2$q == index$3)) begin
            dsb_data$3 = value$2;
            write_address$3 = write_address_q$2$q;
            dsb_write$3 = in_stream_q$2$q;
        end
        if (holds_q$3$q & (dsb_q$3$q == index$3)) begin
            dsb_data$3 = value$3;
            write_address$3 = write_address_q$3$q;
            dsb_write$3 = in_stream_q$3$q;
        end
        buffer0$3$write_clock = clock;
        buffer1$3$write_clock = clock;
        buffer2$3$write_clock = clock;
        buffer0$3$write_address = write_address$3[('h0)+:(17)];
        buffer1$3$write_address = write_address$3[('h0)+:(17)];
        buffer2$3$write_address = write_address$3[('h0)+:(17)];
        buffer0$3$write_data = dsb_data$3;
        buffer1$3$write_data = dsb_data$3;
        buffer2$3$write_data = dsb_data$3;
        buffer0$3$write_enable = write_q$q & dsb_write$3 & (buffer_q$q == buffer_id$0);
        buffer1$3$write_enable = write_q$q & dsb_write$3 & (buffer_q$q == buffer_id$1);
        buffer2$3$write_enable = write_q$q & dsb_write$3 & (buffer_q$q == buffer_id$2);
        read_address = 'h0;
        if (schedule$reading) begin
            read_address = schedule$read_address;
        end
        read_q$d = schedule$reading;
        lane_q$d = schedule$ray & mask;
        cur_q$d = schedule$cur_buffer;
        next_q$d = schedule$next_buffer;
        read_q2$d = read_q$q;
        lane_q2$d = lane_q$q;
        buffer0$0$read_clock = clock;
        buffer1$0$read_clock = clock;
        buffer2$0$read_clock = clock;
        buffer0$0$read_address = read_address[('h0)+:(17)];
        buffer1$0$read_address = read_address[('h0)+:(17)];
        buffer2$0$read_address = read_address[('h0)+:(17)];
        cur_m$0$clock = clock;
        next_m$0$clock = clock;
        cur_m$0$d = 'h0;
        if (cur_q$q == buffer_id$0) begin
            cur_m$0$d = buffer0$0$read_data;
        end
        if (cur_q$q == buffer_id$1) begin
            cur_m$0$d = buffer1$0$read_data;
        end
        if (cur_q$q == buffer_id$2) begin
            cur_m$0$d = buffer2$0$read_data;
        end
        next_m$0$d = 'h0;
        if (next_q$q == buffer_id$0) begin
            next_m$0$d = buffer0$0$read_data;
        end
        if (next_q$q == buffer_id$1) begin
            next_m$0$d = buffer1$0$read_data;
        end
        if (next_q$q == buffer_id$2) begin
            next_m$0$d = buffer2$0$read_data;
        end
        buffer0$1$read_clock = clock;
        buffer1$1$read_clock = clock;
        buffer2$1$read_clock = clock;
        buffer0$1$read_address = read_address[('h0)+:(17)];
        buffer1$1$read_address = read_address[('h0)+:(17)];
        buffer2$1$read_address = read_address[('h0)+:(17)];
        cur_m$1$clock = clock;
        next_m$1$clock = clock;
        cur_m$1$d = 'h0;
        if (cur_q$q == buffer_id$0) begin
            cur_m$1$d = buffer0$1$read_data;
        end
        if (cur_q$q == buffer_id$1) begin
            cur_m$1$d = buffer1$1$read_data;
        end
        if (cur_q$q == buffer_id$2) begin
            cur_m$1$d = buffer2$1$read_data;
        end
        next_m$1$d = 'h0;
        if (next_q$q == buffer_id$0) begin
            next_m$1$d = buffer0$1$read_data;
        end
        if (next_q$q == buffer_id$1) begin
            next_m$1$d = buffer1$1$read_data;
        end
        if (next_q$q == buffer_id$2) begin
            next_m$1$d = buffer2$1$read_data;
        end
        buffer0$2$read_clock = clock;
        buffer1$2$read_clock = clock;
        buffer2$2$read_clock = clock;
        buffer0$2$read_address = read_address[('h0)+:(17)];
        buffer1$2$read_address = read_address[('h0)+:(17)];
        buffer2$2$read_address = read_address[('h0)+:(17)];
        cur_m$2$clock = clock;
        next_m$2$clock = clock;
        cur_m$2$d = 'h0;
        if (cur_q$q == buffer_id$0) begin
            cur_m$2$d = buffer0$2$read_data;
        end
        if (cur_q$q == buffer_id$1) begin
            cur_m$2$d = buffer1$2$read_data;
        end
        if (cur_q$q == buffer_id$2) begin
            cur_m$2$d = buffer2$2$read_data;
        end
        next_m$2$d = 'h0;
        if (next_q$q == buffer_id$0) begin
            next_m$2$d = buffer0$2$read_data;
        end
        if (next_q$q == buffer_id$1) begin
            next_m$2$d = buffer1$2$read_data;
        end
        if (next_q$q == buffer_id$2) begin
            next_m$2$d = buffer2$2$read_data;
        end
        buffer0$3$read_clock = clock;
        buffer1$3$read_clock = clock;
        buffer2$3$read_clock = clock;
        buffer0$3$read_address = read_address[('h0)+:(17)];
        buffer1$3$read_address = read_address[('h0)+:(17)];
        buffer2$3$read_address = read_address[('h0)+:(17)];
        cur_m$3$clock = clock;
        next_m$3$clock = clock;
        cur_m$3$d = 'h0;
        if (cur_q$q == buffer_id$0) begin
            cur_m$3$d = buffer0$3$read_data;
        end
        if (cur_q$q == buffer_id$1) begin
            cur_m$3$d = buffer1$3$read_data;
        end
        if (cur_q$q == buffer_id$2) begin
            cur_m$3$d = buffer2$3$read_data;
        end
        next_m$3$d = 'h0;
        if (next_q$q == buffer_id$0) begin
            next_m$3$d = buffer0$3$read_data;
        end
        if (next_q$q == buffer_id$1) begin
            next_m$3$d = buffer1$3$read_data;
        end
        if (next_q$q == buffer_id$2) begin
            next_m$3$d = buffer2$3$read_data;
        end
        cur$0_pass = 'h0;
        next$0_pass = 'h0;
        if (((index$0 + lane_q2$q) & mask) == index$0) begin
            cur$0_pass = cur_m$0$q;
            next$0_pass = next_m$0$q;
        end
        if (((index$0 + lane_q2$q) & mask) == index$1) begin
            cur$0_pass = cur_m$1$q;
            next$0_pass = next_m$1$q;
        end
        if (((index$0 + lane_q2$q) & mask) == index$2) begin
            cur$0_pass = cur_m$2$q;
            next$0_pass = next_m$2$q;
        end
        if (((index$0 + lane_q2$q) & mask) == index$3) begin
            cur$0_pass = cur_m$3$q;
            next$0_pass = next_m$3$q;
        end
        cur$1_pass = 'h0;
        next$1_pass = 'h0;
        if (((index$1 + lane_q2$q) & mask) == index$0) begin
            cur$1_pass = cur_m$0$q;
            next$1_pass = next_m$0$q;
        end
        if (((index$1 + lane_q2$q) & mask) == index$1) begin
            cur$1_pass = cur_m$1$q;
            next$1_pass = next_m$1$q;
        end
        if (((index$1 + lane_q2$q) & mask) == index$2) begin
            cur$1_pass = cur_m$2$q;
            next$1_pass = next_m$2$q;
        end
        if (((index$1 + lane_q2$q) & mask) == index$3) begin
            cur$1_pass = cur_m$3$q;
            next$1_pass = next_m$3$q;
        end
        cur$2_pass = 'h0;
        next$2_pass = 'h0;
        if (((index$2 + lane_q2$q) & mask) == index$0) begin
            cur$2_pass = cur_m$0$q;
            next$2_pass = next_m$0$q;
        end
        if (((index$2 + lane_q2$q) & mask) == index$1) begin
            cur$2_pass = cur_m$1$q;
            next$2_pass = next_m$1$q;
        end
        if (((index$2 + lane_q2$q) & mask) == index$2) begin
            cur$2_pass = cur_m$2$q;
            next$2_pass = next_m$2$q;
        end
        if (((index$2 + lane_q2$q) & mask) == index$3) begin
            cur$2_pass = cur_m$3$q;
            next$2_pass = next_m$3$q;
        end
        cur$3_pass = 'h0;
        next$3_pass = 'h0;
        if (((index$3 + lane_q2$q) & mask) == index$0) begin
            cur$3_pass = cur_m$0$q;
            next$3_pass = next_m$0$q;
        end
        if (((index$3 + lane_q2$q) & mask) == index$1) begin
            cur$3_pass = cur_m$1$q;
            next$3_pass = next_m$1$q;
        end
        if (((index$3 + lane_q2$q) & mask) == index$2) begin
            cur$3_pass = cur_m$2$q;
            next$3_pass = next_m$2$q;
        end
        if (((index$3 + lane_q2$q) & mask) == index$3) begin
            cur$3_pass = cur_m$3$q;
            next$3_pass = next_m$3$q;
        end
        valid = read_q2$q;
        cur$0 = cur$0_pass;
        cur$1 = cur$1_pass;
        cur$2 = cur$2_pass;
        cur$3 = cur$3_pass;
        next$0 = next$0_pass;
        next$1 = next$1_pass;
        next$2 = next$2_pass;
        next$3 = next$3_pass;
        ext_addr$0 = ext_addr$0_pass;
        ext_addr$1 = ext_addr$1_pass;
        ext_addr$2 = ext_addr$2_pass;
        ext_addr$3 = ext_addr$3_pass;
    end
    
endmodule // top$fetch
module top$fetch$buffer0$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer0$0
module top$fetch$buffer0$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer0$1
module top$fetch$buffer0$2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer0$2
module top$fetch$buffer0$3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer0$3
module top$fetch$buffer1$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer1$0
module top$fetch$buffer1$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer1$1
module top$fetch$buffer1$2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer1$2
module top$fetch$buffer1$3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer1$3
module top$fetch$buffer2$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer2$0
module top$fetch$buffer2$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer2$1
module top$fetch$buffer2$2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer2$2
module top$fetch$buffer2$3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [16:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [16:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[543:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$fetch$buffer2$3
module top$fetch$buffer_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$buffer_q
module top$fetch$buffer_r(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$buffer_r
module top$fetch$cur_m$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_m$0
module top$fetch$cur_m$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_m$1
module top$fetch$cur_m$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_m$2
module top$fetch$cur_m$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_m$3
module top$fetch$cur_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_q
module top$fetch$dsb_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$dsb_q$0
module top$fetch$dsb_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$dsb_q$1
module top$fetch$dsb_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$dsb_q$2
module top$fetch$dsb_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$dsb_q$3
module top$fetch$first_ray_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$first_ray_r
module top$fetch$group(clock,host_write,host_address,host_data,u0,chunk,chunk_next,plane_count,plane,first_ray,x$0,x$1,x$2,x$3,holds$0,holds$1,holds$2,holds$3);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] u0;
    input wire  [23:0] chunk;
    input wire  [23:0] chunk_next;
    input wire  [15:0] plane_count;
    output reg  [15:0] plane;
    output reg  [15:0] first_ray;
    output reg  [15:0] x$0;
    output reg  [15:0] x$1;
    output reg  [15:0] x$2;
    output reg  [15:0] x$3;
    output reg  holds$0;
    output reg  holds$1;
    output reg  holds$2;
    output reg  holds$3;
    
    // Constant declarations
    localparam  perspective = 1'b0;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  index$2 = 16'h2;
    localparam  index$3 = 16'h3;
    localparam  shift = 16'h2;
    
    // Stub signals
    reg  pos_x$clock;
    reg  pos_x$host_write;
    reg  [23:0] pos_x$host_address;
    reg  [63:0] pos_x$host_data;
    reg  [9:0] pos_x$address;
    wire  [15:0] pos_x$data;
    reg  groups$clock;
    reg  groups$host_write;
    reg  [23:0] groups$host_address;
    reg  [63:0] groups$host_data;
    reg  [17:0] groups$address;
    wire  [31:0] groups$data = 'h0;
    reg  group_x$0$clock;
    reg  group_x$0$host_write;
    reg  [23:0] group_x$0$host_address;
    reg  [63:0] group_x$0$host_data;
    reg  [17:0] group_x$0$address;
    wire  [16:0] group_x$0$data = 'h0;
    reg  group_x$1$clock;
    reg  group_x$1$host_write;
    reg  [23:0] group_x$1$host_address;
    reg  [63:0] group_x$1$host_data;
    reg  [17:0] group_x$1$address;
    wire  [16:0] group_x$1$data = 'h0;
    reg  group_x$2$clock;
    reg  group_x$2$host_write;
    reg  [23:0] group_x$2$host_address;
    reg  [63:0] group_x$2$host_data;
    reg  [17:0] group_x$2$address;
    wire  [16:0] group_x$2$data = 'h0;
    reg  group_x$3$clock;
    reg  group_x$3$host_write;
    reg  [23:0] group_x$3$host_address;
    reg  [63:0] group_x$3$host_data;
    reg  [17:0] group_x$3$address;
    wire  [16:0] group_x$3$data = 'h0;
    
    // Local signals
    reg  [15:0] chunk_ray;
    reg  [15:0] x0;
    
    // Sub module instances
    top$fetch$group$pos_x pos_x(
        .clock(pos_x$clock),
        .host_write(pos_x$host_write),
        .host_address(pos_x$host_address),
        .host_data(pos_x$host_data),
        .address(pos_x$address),
        .data(pos_x$data)
    );
    
    // Update code
    reg  [15:0] plane_pass;
    reg  [15:0] first_ray_pass;
    reg  [15:0] x$0_pass;
    reg  [15:0] x$1_pass;
    reg  [15:0] x$2_pass;
    reg  [15:0] x$3_pass;
    reg  holds$0_pass;
    reg  holds$1_pass;
    reg  holds$2_pass;
    reg  holds$3_pass;
    always @(*) begin
        pos_x$clock = clock;
        pos_x$host_write = host_write;
        pos_x$host_address = host_address;
        pos_x$host_data = host_data;
        groups$clock = clock;
        groups$host_write = host_write;
        groups$host_address = host_address;
        groups$host_data = host_data;
        pos_x$address = plane_count[('h0)+:(10)];
        groups$address = chunk_next[('h0)+:(18)];
        chunk_ray = chunk[('h0)+:(16)] << shift;
        x0 = u0 + pos_x$data + chunk_ray;
        plane_pass = plane_count;
        first_ray_pass = chunk_ray;
        if (perspective) begin
            plane_pass = groups$data[('h0)+:(16)];
            first_ray_pass = groups$data[('h10)+:(16)];
        end
        group_x$0$clock = clock;
        group_x$0$host_write = host_write;
        group_x$0$host_address = host_address;
        group_x$0$host_data = host_data;
        group_x$0$address = chunk_next[('h0)+:(18)];
        x$0_pass = x0 + index$0;
        holds$0_pass = 1'b1;
        if (perspective) begin
            x$0_pass = group_x$0$data[('h0)+:(16)];
            holds$0_pass = group_x$0$data['h10];
        end
        group_x$1$clock = clock;
        group_x$1$host_write = host_write;
        group_x$1$host_address = host_address;
        group_x$1$host_data = host_data;
        group_x$1$address = chunk_next[('h0)+:(18)];
        x$1_pass = x0 + index$1;
        holds$1_pass = 1'b1;
        if (perspective) begin
            x$1_pass = group_x$1$data[('h0)+:(16)];
            holds$1_pass = group_x$1$data['h10];
        end
        group_x$2$clock = clock;
        group_x$2$host_write = host_write;
        group_x$2$host_address = host_address;
        group_x$2$host_data = host_data;
        group_x$2$address = chunk_next[('h0)+:(18)];
        x$2_pass = x0 + index$2;
        holds$2_pass = 1'b1;
        if (perspective) begin
            x$2_pass = group_x$2$data[('h0)+:(16)];
            holds$2_pass = group_x$2$data['h10];
        end
        group_x$3$clock = clock;
        group_x$3$host_write = host_write;
        group_x$3$host_address = host_address;
        group_x$3$host_data = host_data;
        group_x$3$address = chunk_next[('h0)+:(18)];
        x$3_pass = x0 + index$3;
        holds$3_pass = 1'b1;
        if (perspective) begin
            x$3_pass = group_x$3$data[('h0)+:(16)];
            holds$3_pass = group_x$3$data['h10];
        end
        plane = plane_pass;
        first_ray = first_ray_pass;
        x$0 = x$0_pass;
        x$1 = x$1_pass;
        x$2 = x$2_pass;
        x$3 = x$3_pass;
        holds$0 = holds$0_pass;
        holds$1 = holds$1_pass;
        holds$2 = holds$2_pass;
        holds$3 = holds$3_pass;
    end
    
endmodule // top$fetch$group
module top$fetch$group$pos_x(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[63:0];
    integer i;
    initial begin
       for (i = 0; i <= 63; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[5:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd458752 && host_address < 24'd458816) begin
          mem[host_address[5:0]] <= host_data[15:0];
       end
    end
endmodule // top$fetch$group$pos_x
module top$fetch$holds_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_q$0
module top$fetch$holds_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_q$1
module top$fetch$holds_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_q$2
module top$fetch$holds_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_q$3
module top$fetch$holds_r$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_r$0
module top$fetch$holds_r$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_r$1
module top$fetch$holds_r$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_r$2
module top$fetch$holds_r$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$holds_r$3
module top$fetch$in_stream_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$in_stream_q$0
module top$fetch$in_stream_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$in_stream_q$1
module top$fetch$in_stream_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$in_stream_q$2
module top$fetch$in_stream_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$in_stream_q$3
module top$fetch$inside_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$0
module top$fetch$inside_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$1
module top$fetch$inside_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$2
module top$fetch$inside_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$3
module top$fetch$lane_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$lane_q
module top$fetch$lane_q2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$lane_q2
module top$fetch$memory$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[8191:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[12:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[12:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$0
module top$fetch$memory$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[8191:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[12:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[12:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$1
module top$fetch$memory$2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[8191:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[12:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[12:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$2
module top$fetch$memory$3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[8191:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[12:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[12:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$3
module top$fetch$module_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$module_q$0
module top$fetch$module_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$module_q$1
module top$fetch$module_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$module_q$2
module top$fetch$module_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$module_q$3
module top$fetch$next_m$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_m$0
module top$fetch$next_m$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_m$1
module top$fetch$next_m$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_m$2
module top$fetch$next_m$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_m$3
module top$fetch$next_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_q
module top$fetch$period_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$period_r
module top$fetch$plane_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$plane_r
module top$fetch$pos_y(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [17:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h200000;
    localparam  window = 24'h240000;
    
    // Stub signals
    reg  [17:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [17:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$fetch$pos_y$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 18'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$fetch$pos_y
module top$fetch$pos_y$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [17:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [17:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [15:0] mem[63:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[5:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[5:0]] <= write_data;
       end
    end
endmodule // top$fetch$pos_y$ram
module top$fetch$read_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$read_q
module top$fetch$read_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$read_q2
module top$fetch$regs(clock,host_write,host_address,host_data,q$0,q$1,q$2,q$3);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    output reg  [63:0] q$2;
    output reg  [63:0] q$3;
    
    // Constant declarations
    localparam  address$0 = 24'h30;
    localparam  address$1 = 24'h31;
    localparam  address$2 = 24'h32;
    localparam  address$3 = 24'h33;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    reg  [63:0] r$2$d;
    wire  [63:0] r$2$q;
    reg  r$2$clock;
    reg  [63:0] r$3$d;
    wire  [63:0] r$3$q;
    reg  r$3$clock;
    
    // Sub module instances
    top$fetch$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$fetch$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    top$fetch$regs$r$2 r$2(
        .d(r$2$d),
        .q(r$2$q),
        .clock(r$2$clock)
    );
    top$fetch$regs$r$3 r$3(
        .d(r$3$d),
        .q(r$3$q),
        .clock(r$3$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
        r$2$clock = clock;
        r$2$d = r$2$q;
        if (host_write & (host_address == address$2)) begin
            r$2$d = host_data;
        end
        q$2 = r$2$q;
        r$3$clock = clock;
        r$3$d = r$3$q;
        if (host_write & (host_address == address$3)) begin
            r$3$d = host_data;
        end
        q$3 = r$3$q;
    end
    
endmodule // top$fetch$regs
module top$fetch$regs$r$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$regs$r$0
module top$fetch$regs$r$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$regs$r$1
module top$fetch$regs$r$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$regs$r$2
module top$fetch$regs$r$3(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$regs$r$3
module top$fetch$row_base_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$row_base_r
module top$fetch$s1_buffer(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_buffer
module top$fetch$s1_holds$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_holds$0
module top$fetch$s1_holds$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_holds$1
module top$fetch$s1_holds$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_holds$2
module top$fetch$s1_holds$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_holds$3
module top$fetch$s1_plane(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_plane
module top$fetch$s1_plane_offset(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_plane_offset
module top$fetch$s1_ray$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_ray$0
module top$fetch$s1_ray$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_ray$1
module top$fetch$s1_ray$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_ray$2
module top$fetch$s1_ray$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_ray$3
module top$fetch$s1_row(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_row
module top$fetch$s1_writing(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_writing
module top$fetch$s1_x$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_x$0
module top$fetch$s1_x$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_x$1
module top$fetch$s1_x$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_x$2
module top$fetch$s1_x$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s1_x$3
module top$fetch$s2_address$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_address$0
module top$fetch$s2_address$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_address$1
module top$fetch$s2_address$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_address$2
module top$fetch$s2_address$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_address$3
module top$fetch$s2_buffer(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_buffer
module top$fetch$s2_dsb$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_dsb$0
module top$fetch$s2_dsb$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_dsb$1
module top$fetch$s2_dsb$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_dsb$2
module top$fetch$s2_dsb$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_dsb$3
module top$fetch$s2_holds$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_holds$0
module top$fetch$s2_holds$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_holds$1
module top$fetch$s2_holds$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_holds$2
module top$fetch$s2_holds$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_holds$3
module top$fetch$s2_in_stream$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_in_stream$0
module top$fetch$s2_in_stream$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_in_stream$1
module top$fetch$s2_in_stream$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_in_stream$2
module top$fetch$s2_in_stream$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_in_stream$3
module top$fetch$s2_inside$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_inside$0
module top$fetch$s2_inside$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_inside$1
module top$fetch$s2_inside$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_inside$2
module top$fetch$s2_inside$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_inside$3
module top$fetch$s2_module$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_module$0
module top$fetch$s2_module$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_module$1
module top$fetch$s2_module$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_module$2
module top$fetch$s2_module$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_module$3
module top$fetch$s2_write_address$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_write_address$0
module top$fetch$s2_write_address$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_write_address$1
module top$fetch$s2_write_address$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_write_address$2
module top$fetch$s2_write_address$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_write_address$3
module top$fetch$s2_writing(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$s2_writing
module top$fetch$schedule(clock,start,writing,plane,chunk,chunk_next,period,period_next,write_buffer,reading,ray,read_address,cur_buffer,next_buffer,host_write,host_address,host_data);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    output reg  writing;
    output reg  [15:0] plane;
    output reg  [23:0] chunk;
    output reg  [23:0] chunk_next;
    output reg  [15:0] period;
    output reg  [15:0] period_next;
    output reg  [1:0] write_buffer;
    output reg  reading;
    output reg  [15:0] ray;
    output reg  [31:0] read_address;
    output reg  [1:0] cur_buffer;
    output reg  [1:0] next_buffer;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    
    // Constant declarations
    localparam  first_read_period = 16'h2;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    reg  active$d;
    wire  active$q;
    reg  active$clock;
    reg  [23:0] tick$d;
    wire  [23:0] tick$q;
    reg  tick$clock;
    reg  [15:0] period_q$d;
    wire  [15:0] period_q$q;
    reg  period_q$clock;
    reg  [15:0] plane_q$d;
    wire  [15:0] plane_q$q;
    reg  plane_q$clock;
    reg  [23:0] chunk_q$d;
    wire  [23:0] chunk_q$q;
    reg  chunk_q$clock;
    reg  [15:0] ray_q$d;
    wire  [15:0] ray_q$q;
    reg  ray_q$clock;
    reg  [15:0] segment_q$d;
    wire  [15:0] segment_q$q;
    reg  segment_q$clock;
    reg  [31:0] address_q$d;
    wire  [31:0] address_q$q;
    reg  address_q$clock;
    reg  written$d;
    wire  written$q;
    reg  written$clock;
    reg  read$d;
    wire  read$q;
    reg  read$clock;
    reg  [1:0] w_q$d;
    wire  [1:0] w_q$q;
    reg  w_q$clock;
    reg  [1:0] c_q$d;
    wire  [1:0] c_q$q;
    reg  c_q$clock;
    reg  [1:0] n_q$d;
    wire  [1:0] n_q$q;
    reg  n_q$clock;
    
    // Local signals
    reg  [23:0] last_tick;
    reg  [15:0] last_write_period;
    reg  [15:0] last_plane;
    reg  [23:0] last_chunk;
    reg  [15:0] last_ray;
    reg  [15:0] last_segment;
    reg  [15:0] last_period;
    
    // Sub module instances
    top$fetch$schedule$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1)
    );
    top$fetch$schedule$active active(
        .d(active$d),
        .q(active$q),
        .clock(active$clock)
    );
    top$fetch$schedule$tick tick(
        .d(tick$d),
        .q(tick$q),
        .clock(tick$clock)
    );
    top$fetch$schedule$period_q period_q(
        .d(period_q$d),
        .q(period_q$q),
        .clock(period_q$clock)
    );
    top$fetch$schedule$plane_q plane_q(
        .d(plane_q$d),
        .q(plane_q$q),
        .clock(plane_q$clock)
    );
    top$fetch$schedule$chunk_q chunk_q(
        .d(chunk_q$d),
        .q(chunk_q$q),
        .clock(chunk_q$clock)
    );
    top$fetch$schedule$ray_q ray_q(
        .d(ray_q$d),
        .q(ray_q$q),
        .clock(ray_q$clock)
    );
    top$fetch$schedule$segment_q segment_q(
        .d(segment_q$d),
        .q(segment_q$q),
        .clock(segment_q$clock)
    );
    top$fetch$schedule$address_q address_q(
        .d(address_q$d),
        .q(address_q$q),
        .clock(address_q$clock)
    );
    top$fetch$schedule$written written(
        .d(written$d),
        .q(written$q),
        .clock(written$clock)
    );
    top$fetch$schedule$read read(
        .d(read$d),
        .q(read$q),
        .clock(read$clock)
    );
    top$fetch$schedule$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$fetch$schedule$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$fetch$schedule$n_q n_q(
        .d(n_q$d),
        .q(n_q$q),
        .clock(n_q$clock)
    );
    
    // Update code
    always @(*) begin
        active$clock = clock;
        tick$clock = clock;
        period_q$clock = clock;
        plane_q$clock = clock;
        chunk_q$clock = clock;
        ray_q$clock = clock;
        segment_q$clock = clock;
        address_q$clock = clock;
        written$clock = clock;
        read$clock = clock;
        w_q$clock = clock;
        c_q$clock = clock;
        n_q$clock = clock;
        active$d = active$q;
        tick$d = tick$q;
        period_q$d = period_q$q;
        plane_q$d = plane_q$q;
        chunk_q$d = chunk_q$q;
        ray_q$d = ray_q$q;
        segment_q$d = segment_q$q;
        address_q$d = address_q$q;
        written$d = written$q;
        read$d = read$q;
        w_q$d = w_q$q;
        c_q$d = c_q$q;
        n_q$d = n_q$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        last_ray = regs$q$0[('h0)+:(16)] - 'h1;
        last_write_period = regs$q$0[('h10)+:(16)];
        last_segment = regs$q$0[('h20)+:(16)] - 'h1;
        last_tick = regs$q$1[('h0)+:(24)];
        last_chunk = regs$q$1[('h18)+:(24)];
        last_plane = regs$q$1[('h30)+:(16)];
        last_period = last_write_period + 'h1;
        writing = active$q & ~written$q & (period_q$q <= last_write_period);
        reading = active$q & ~read$q & (period_q$q >= first_read_period);
        if (writing) begin
            chunk_q$d = chunk_q$q + 'h1;
            if (chunk_q$q == last_chunk) begin
                chunk_q$d = 'h0;
                plane_q$d = plane_q$q + 'h1;
                if (plane_q$q == last_plane) begin
                    written$d = 1'b1;
                end
            end
        end
        if (reading) begin
            segment_q$d = segment_q$q + 'h1;
            address_q$d = address_q$q + 'h1;
            if (segment_q$q == last_segment) begin
                segment_q$d = 'h0;
                ray_q$d = ray_q$q + 'h1;
                if (ray_q$q == last_ray) begin
                    read$d = 1'b1;
                end
            end
        end
        if (active$q) begin
            tick$d = tick$q + 'h1;
            if (tick$q == last_tick) begin
                tick$d = 'h0;
                period_q$d = period_q$q + 'h1;
                if (period_q$q == last_period) begin
                    active$d = 1'b0;
                end
                chunk_q$d = 'h0;
                plane_q$d = 'h0;
                segment_q$d = 'h0;
                ray_q$d = 'h0;
                address_q$d = 'h0;
                written$d = 1'b0;
                read$d = 1'b0;
                c_q$d = n_q$q;
                n_q$d = w_q$q;
                w_q$d = c_q$q;
            end
        end
        if (start) begin
            active$d = 1'b1;
            tick$d = 'h0;
            period_q$d = 'h0;
            chunk_q$d = 'h0;
            plane_q$d = 'h0;
            segment_q$d = 'h0;
            ray_q$d = 'h0;
            address_q$d = 'h0;
            written$d = 1'b0;
            read$d = 1'b0;
            w_q$d = 'h0;
            n_q$d = 'h2;
            c_q$d = 'h1;
        end
        plane = plane_q$q;
        chunk = chunk_q$q;
        chunk_next = chunk_q$d;
        period = period_q$q;
        period_next = period_q$d;
        write_buffer = w_q$q;
        ray = ray_q$q;
        read_address = address_q$q;
        cur_buffer = c_q$q;
        next_buffer = n_q$q;
    end
    
endmodule // top$fetch$schedule
module top$fetch$schedule$active(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$active
module top$fetch$schedule$address_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$address_q
module top$fetch$schedule$c_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$c_q
module top$fetch$schedule$chunk_q(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$chunk_q
module top$fetch$schedule$n_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$n_q
module top$fetch$schedule$period_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$period_q
module top$fetch$schedule$plane_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$plane_q
module top$fetch$schedule$ray_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$ray_q
module top$fetch$schedule$read(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$read
module top$fetch$schedule$regs(clock,host_write,host_address,host_data,q$0,q$1);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    
    // Constant declarations
    localparam  address$0 = 24'h30;
    localparam  address$1 = 24'h34;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    
    // Sub module instances
    top$fetch$schedule$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$fetch$schedule$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
    end
    
endmodule // top$fetch$schedule$regs
module top$fetch$schedule$regs$r$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$regs$r$0
module top$fetch$schedule$regs$r$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$regs$r$1
module top$fetch$schedule$segment_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$segment_q
module top$fetch$schedule$tick(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$tick
module top$fetch$schedule$w_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$w_q
module top$fetch$schedule$written(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$written
module top$fetch$write_address_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_address_q$0
module top$fetch$write_address_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_address_q$1
module top$fetch$write_address_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_address_q$2
module top$fetch$write_address_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_address_q$3
module top$fetch$write_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_q
module top$fetch$writing_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$writing_r
module top$fetch$x_r$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$x_r$0
module top$fetch$x_r$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$x_r$1
module top$fetch$x_r$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$x_r$2
module top$fetch$x_r$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$x_r$3
