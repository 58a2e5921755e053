module top$fetch(clock,start,valid,cur$0,cur$1,next$0,next$1,ext_addr$0,ext_addr$1,ext_data$0,ext_data$1,load_enable,load_module,load_address,load_data);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    output reg  valid;
    output reg  [15:0] cur$0;
    output reg  [15:0] cur$1;
    output reg  [15:0] next$0;
    output reg  [15:0] next$1;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [31:0] load_address;
    input wire  [15:0] load_data;
    
    // Constant declarations
    localparam  external = 1'b0;
    localparam  row_stride = 16'h15;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  module_id$0 = 8'h0;
    localparam  module_id$1 = 8'h1;
    localparam  buffer_id$0 = 2'b0;
    localparam  buffer_id$1 = 2'b1;
    localparam  buffer_id$2 = 2'b10;
    localparam  one = 16'h1;
    localparam  mask = 16'h1;
    localparam  shift = 16'h1;
    localparam  n_x = 16'h12;
    localparam  n_y = 16'h10;
    localparam  n_k = 16'h14;
    localparam  row_words = 16'h9;
    localparam  plane_words = 16'h90;
    localparam  v0 = 16'hfff6;
    localparam  rays = 16'h10;
    localparam  segments = 16'ha;
    
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
    reg  [15:0] buffer0$0$read_address;
    reg  buffer0$0$read_clock;
    wire  [15:0] buffer0$0$read_data;
    reg  [15:0] buffer0$0$write_address;
    reg  buffer0$0$write_clock;
    reg  [15:0] buffer0$0$write_data;
    reg  buffer0$0$write_enable;
    reg  [15:0] buffer0$1$read_address;
    reg  buffer0$1$read_clock;
    wire  [15:0] buffer0$1$read_data;
    reg  [15:0] buffer0$1$write_address;
    reg  buffer0$1$write_clock;
    reg  [15:0] buffer0$1$write_data;
    reg  buffer0$1$write_enable;
    reg  [15:0] buffer1$0$read_address;
    reg  buffer1$0$read_clock;
    wire  [15:0] buffer1$0$read_data;
    reg  [15:0] buffer1$0$write_address;
    reg  buffer1$0$write_clock;
    reg  [15:0] buffer1$0$write_data;
    reg  buffer1$0$write_enable;
    reg  [15:0] buffer1$1$read_address;
    reg  buffer1$1$read_clock;
    wire  [15:0] buffer1$1$read_data;
    reg  [15:0] buffer1$1$write_address;
    reg  buffer1$1$write_clock;
    reg  [15:0] buffer1$1$write_data;
    reg  buffer1$1$write_enable;
    reg  [15:0] buffer2$0$read_address;
    reg  buffer2$0$read_clock;
    wire  [15:0] buffer2$0$read_data;
    reg  [15:0] buffer2$0$write_address;
    reg  buffer2$0$write_clock;
    reg  [15:0] buffer2$0$write_data;
    reg  buffer2$0$write_enable;
    reg  [15:0] buffer2$1$read_address;
    reg  buffer2$1$read_clock;
    wire  [15:0] buffer2$1$read_data;
    reg  [15:0] buffer2$1$write_address;
    reg  buffer2$1$write_clock;
    reg  [15:0] buffer2$1$write_data;
    reg  buffer2$1$write_enable;
    reg  [15:0] group$chunk;
    reg  [15:0] group$plane_count;
    wire  [15:0] group$plane;
    wire  [15:0] group$first_ray;
    wire  [15:0] group$x$0;
    wire  [15:0] group$x$1;
    wire  group$holds$0;
    wire  group$holds$1;
    reg  [31:0] pos_y$address;
    wire  [15:0] pos_y$data;
    reg  schedule$clock;
    reg  schedule$start;
    wire  schedule$writing;
    wire  [15:0] schedule$plane;
    wire  [15:0] schedule$chunk;
    wire  [15:0] schedule$period;
    wire  [1:0] schedule$write_buffer;
    wire  schedule$reading;
    wire  [15:0] schedule$ray;
    wire  [15:0] schedule$segment;
    wire  [1:0] schedule$cur_buffer;
    wire  [1:0] schedule$next_buffer;
    reg  holds_q$0$d;
    wire  holds_q$0$q;
    reg  holds_q$0$clock;
    reg  holds_q$1$d;
    wire  holds_q$1$q;
    reg  holds_q$1$clock;
    reg  inside_q$0$d;
    wire  inside_q$0$q;
    reg  inside_q$0$clock;
    reg  inside_q$1$d;
    wire  inside_q$1$q;
    reg  inside_q$1$clock;
    reg  [15:0] module_q$0$d;
    wire  [15:0] module_q$0$q;
    reg  module_q$0$clock;
    reg  [15:0] module_q$1$d;
    wire  [15:0] module_q$1$q;
    reg  module_q$1$clock;
    reg  [15:0] ray_q$0$d;
    wire  [15:0] ray_q$0$q;
    reg  ray_q$0$clock;
    reg  [15:0] ray_q$1$d;
    wire  [15:0] ray_q$1$q;
    reg  ray_q$1$clock;
    reg  [15:0] plane_q$d;
    wire  [15:0] plane_q$q;
    reg  plane_q$clock;
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
    
    // Local signals
    reg  [15:0] word$0;
    reg  [15:0] word$1;
    reg  [31:0] row_entry;
    reg  [15:0] row;
    reg  [15:0] lane_ray$0;
    reg  [15:0] lane_ray$1;
    reg  lane_inside$0;
    reg  lane_inside$1;
    reg  [15:0] lane_module$0;
    reg  [15:0] lane_module$1;
    reg  [15:0] lane_column$0;
    reg  [15:0] lane_column$1;
    reg  [31:0] lane_address$0;
    reg  [31:0] lane_address$1;
    reg  [31:0] address$0;
    reg  [31:0] address$1;
    reg  reads$0;
    reg  reads$1;
    reg  [15:0] plane_segment;
    reg  [15:0] value$0;
    reg  [15:0] value$1;
    reg  [15:0] dsb_data$0;
    reg  [15:0] dsb_data$1;
    reg  [15:0] dsb_ray$0;
    reg  [15:0] dsb_ray$1;
    reg  dsb_write$0;
    reg  dsb_write$1;
    reg  [31:0] write_address$0;
    reg  [31:0] write_address$1;
    reg  [31:0] read_address;
    
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
    top$fetch$group group(
        .chunk(group$chunk),
        .plane_count(group$plane_count),
        .plane(group$plane),
        .first_ray(group$first_ray),
        .x$0(group$x$0),
        .x$1(group$x$1),
        .holds$0(group$holds$0),
        .holds$1(group$holds$1)
    );
    top$fetch$pos_y pos_y(
        .address(pos_y$address),
        .data(pos_y$data)
    );
    top$fetch$schedule schedule(
        .clock(schedule$clock),
        .start(schedule$start),
        .writing(schedule$writing),
        .plane(schedule$plane),
        .chunk(schedule$chunk),
        .period(schedule$period),
        .write_buffer(schedule$write_buffer),
        .reading(schedule$reading),
        .ray(schedule$ray),
        .segment(schedule$segment),
        .cur_buffer(schedule$cur_buffer),
        .next_buffer(schedule$next_buffer)
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
    top$fetch$ray_q$0 ray_q$0(
        .d(ray_q$0$d),
        .q(ray_q$0$q),
        .clock(ray_q$0$clock)
    );
    top$fetch$ray_q$1 ray_q$1(
        .d(ray_q$1$d),
        .q(ray_q$1$q),
        .clock(ray_q$1$clock)
    );
    top$fetch$plane_q plane_q(
        .d(plane_q$d),
        .q(plane_q$q),
        .clock(plane_q$clock)
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
    
    // Update code
    reg  [15:0] cur$0_pass;
    reg  [15:0] cur$1_pass;
    reg  [15:0] next$0_pass;
    reg  [15:0] next$1_pass;
    reg  [31:0] ext_addr$0_pass;
    reg  [31:0] ext_addr$1_pass;
    always @(*) begin
        plane_q$clock = clock;
        write_q$clock = clock;
        buffer_q$clock = clock;
        read_q$clock = clock;
        lane_q$clock = clock;
        cur_q$clock = clock;
        next_q$clock = clock;
        plane_q$d = plane_q$q;
        write_q$d = write_q$q;
        buffer_q$d = buffer_q$q;
        read_q$d = read_q$q;
        lane_q$d = lane_q$q;
        cur_q$d = cur_q$q;
        next_q$d = next_q$q;
        schedule$clock = clock;
        schedule$start = start;
        group$chunk = schedule$chunk;
        group$plane_count = schedule$plane;
        row_entry = schedule$period * row_stride + 32'(group$plane);
        pos_y$address = row_entry;
        row = v0 + schedule$period + pos_y$data;
        lane_ray$0 = group$first_ray + index$0;
        lane_inside$0 = group$holds$0 & ~group$x$0['hf] & (group$x$0 < n_x) & ~row['hf] & (row < n_y) & (group$plane < n_k);
        lane_module$0 = (group$x$0 + row + group$plane) & mask;
        lane_column$0 = group$x$0 >> shift;
        lane_address$0 = lane_column$0 * one + row * row_words + group$plane * plane_words;
        holds_q$0$clock = clock;
        inside_q$0$clock = clock;
        module_q$0$clock = clock;
        ray_q$0$clock = clock;
        holds_q$0$d = group$holds$0;
        inside_q$0$d = lane_inside$0;
        module_q$0$d = lane_module$0;
        ray_q$0$d = lane_ray$0;
        lane_ray$1 = group$first_ray + index$1;
        lane_inside$1 = group$holds$1 & ~group$x$1['hf] & (group$x$1 < n_x) & ~row['hf] & (row < n_y) & (group$plane < n_k);
        lane_module$1 = (group$x$1 + row + group$plane) & mask;
        lane_column$1 = group$x$1 >> shift;
        lane_address$1 = lane_column$1 * one + row * row_words + group$plane * plane_words;
        holds_q$1$clock = clock;
        inside_q$1$clock = clock;
        module_q$1$clock = clock;
        ray_q$1$clock = clock;
        holds_q$1$d = group$holds$1;
        inside_q$1$d = lane_inside$1;
        module_q$1$d = lane_module$1;
        ray_q$1$d = lane_ray$1;
        address$0 = 'h0;
        reads$0 = 1'b0;
        if (lane_inside$0 & (lane_module$0 == index$0)) begin
            address$0 = lane_address$0;
            reads$0 = 1'b1;
        end
        if (lane_inside$1 & (lane_module$1 == index$0)) begin
            address$0 = lane_address$1;
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
        if (lane_inside$0 & (lane_module$0 == index$1)) begin
            address$1 = lane_address$0;
            reads$1 = 1'b1;
        end
        if (lane_inside$1 & (lane_module$1 == index$1)) begin
            address$1 = lane_address$1;
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
        plane_q$d = group$plane;
        write_q$d = schedule$writing;
        plane_segment = plane_q$q >> shift;
        buffer_q$d = schedule$write_buffer;
        value$0 = 'h0;
        if (inside_q$0$q & (module_q$0$q == index$0)) begin
            value$0 = word$0;
        end
        if (inside_q$0$q & (module_q$0$q == index$1)) begin
            value$0 = word$1;
        end
        value$1 = 'h0;
        if (inside_q$1$q & (module_q$1$q == index$0)) begin
            value$1 = word$0;
        end
        if (inside_q$1$q & (module_q$1$q == index$1)) begin
            value$1 = word$1;
        end
        dsb_data$0 = 'h0;
        dsb_ray$0 = 'h0;
        dsb_write$0 = 1'b0;
        if (holds_q$0$q & (((ray_q$0$q + plane_q$q) & mask) == index$0)) begin
            dsb_data$0 = value$0;
            dsb_ray$0 = ray_q$0$q;
            dsb_write$0 = 1'b1;
        end
        if (holds_q$1$q & (((ray_q$1$q + plane_q$q) & mask) == index$0)) begin
            dsb_data$0 = value$1;
            dsb_ray$0 = ray_q$1$q;
            dsb_write$0 = 1'b1;
        end
        write_address$0 = dsb_ray$0 * segments + 32'(plane_segment);
        buffer0$0$write_clock = clock;
        buffer1$0$write_clock = clock;
        buffer2$0$write_clock = clock;
        buffer0$0$write_address = write_address$0[('h0)+:(16)];
        buffer1$0$write_address = write_address$0[('h0)+:(16)];
        buffer2$0$write_address = write_address$0[('h0)+:(16)];
        buffer0$0$write_data = dsb_data$0;
        buffer1$0$write_data = dsb_data$0;
        buffer2$0$write_data = dsb_data$0;
        buffer0$0$write_enable = write_q$q & dsb_write$0 & (dsb_ray$0 < rays) & (buffer_q$q == buffer_id$0);
        buffer1$0$write_enable = write_q$q & dsb_write$0 & (dsb_ray$0 < rays) & (buffer_q$q == buffer_id$1);
        buffer2$0$write_enable = write_q$q & dsb_write$0 & (dsb_ray$0 < rays) & (buffer_q$q == buffer_id$2);
        dsb_data$1 = 'h0;
        dsb_ray$1 = 'h0;
        dsb_write$1 = 1'b0;
        if (holds_q$0$q & (((ray_q$0$q + plane_q$q) & mask) == index$1)) begin
            dsb_data$1 = value$0;
            dsb_ray$1 = ray_q$0$q;
            dsb_write$1 = 1'b1;
        end
        if (holds_q$1$q & (((ray_q$1$q + plane_q$q) & mask) == index$1)) begin
            dsb_data$1 = value$1;
            dsb_ray$1 = ray_q$1$q;
            dsb_write$1 = 1'b1;
        end
        write_address$1 = dsb_ray$1 * segments + 32'(plane_segment);
        buffer0$1$write_clock = clock;
        buffer1$1$write_clock = clock;
        buffer2$1$write_clock = clock;
        buffer0$1$write_address = write_address$1[('h0)+:(16)];
        buffer1$1$write_address = write_address$1[('h0)+:(16)];
        buffer2$1$write_address = write_address$1[('h0)+:(16)];
        buffer0$1$write_data = dsb_data$1;
        buffer1$1$write_data = dsb_data$1;
        buffer2$1$write_data = dsb_data$1;
        buffer0$1$write_enable = write_q$q & dsb_write$1 & (dsb_ray$1 < rays) & (buffer_q$q == buffer_id$0);
        buffer1$1$write_enable = write_q$q & dsb_write$1 & (dsb_ray$1 < rays) & (buffer_q$q == buffer_id$1);
        buffer2$1$write_enable = write_q$q & dsb_write$1 & (dsb_ray$1 < rays) & (buffer_q$q == buffer_id$2);
        read_address = 'h0;
        if (schedule$reading) begin
            read_address = schedule$ray * segments + 32'(schedule$segment);
        end
        read_q$d = schedule$reading;
        lane_q$d = schedule$ray & mask;
        cur_q$d = schedule$cur_buffer;
        next_q$d = schedule$next_buffer;
        buffer0$0$read_clock = clock;
        buffer1$0$read_clock = clock;
        buffer2$0$read_clock = clock;
        buffer0$0$read_address = read_address[('h0)+:(16)];
        buffer1$0$read_address = read_address[('h0)+:(16)];
        buffer2$0$read_address = read_address[('h0)+:(16)];
        buffer0$1$read_clock = clock;
        buffer1$1$read_clock = clock;
        buffer2$1$read_clock = clock;
        buffer0$1$read_address = read_address[('h0)+:(16)];
        buffer1$1$read_address = read_address[('h0)+:(16)];
        buffer2$1$read_address = read_address[('h0)+:(16)];
        cur$0_pass = 'h0;
        next$0_pass = 'h0;
        if (((index$0 + lane_q$q) & mask) == index$0) begin
            if (cur_q$q == buffer_id$0) begin
                cur$0_pass = buffer0$0$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$0_pass = buffer1$0$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$0_pass = buffer2$0$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$0_pass = buffer0$0$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$0_pass = buffer1$0$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$0_pass = buffer2$0$read_data;
            end
        end
        if (((index$0 + lane_q$q) & mask) == index$1) begin
            if (cur_q$q == buffer_id$0) begin
                cur$0_pass = buffer0$1$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$0_pass = buffer1$1$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$0_pass = buffer2$1$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$0_pass = buffer0$1$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$0_pass = buffer1$1$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$0_pass = buffer2$1$read_data;
            end
        end
        cur$1_pass = 'h0;
        next$1_pass = 'h0;
        if (((index$1 + lane_q$q) & mask) == index$0) begin
            if (cur_q$q == buffer_id$0) begin
                cur$1_pass = buffer0$0$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$1_pass = buffer1$0$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$1_pass = buffer2$0$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$1_pass = buffer0$0$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$1_pass = buffer1$0$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$1_pass = buffer2$0$read_data;
            end
        end
        if (((index$1 + lane_q$q) & mask) == index$1) begin
            if (cur_q$q == buffer_id$0) begin
                cur$1_pass = buffer0$1$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$1_pass = buffer1$1$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$1_pass = buffer2$1$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$1_pass = buffer0$1$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$1_pass = buffer1$1$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$1_pass = buffer2$1$read_data;
            end
        end
        valid = read_q$q;
        cur$0 = cur$0_pass;
        cur$1 = cur$1_pass;
        next$0 = next$0_pass;
        next$1 = next$1_pass;
        ext_addr$0 = ext_addr$0_pass;
        ext_addr$1 = ext_addr$1_pass;
    end
    
endmodule // top$fetch
module top$fetch$buffer0$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer0$0
module top$fetch$buffer0$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer0$1
module top$fetch$buffer1$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer1$0
module top$fetch$buffer1$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer1$1
module top$fetch$buffer2$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer2$0
module top$fetch$buffer2$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[159:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer2$1
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
module top$fetch$group(chunk,plane_count,plane,first_ray,x$0,x$1,holds$0,holds$1);
    
    // Module arguments
    input wire  [15:0] chunk;
    input wire  [15:0] plane_count;
    output reg  [15:0] plane;
    output reg  [15:0] first_ray;
    output reg  [15:0] x$0;
    output reg  [15:0] x$1;
    output reg  holds$0;
    output reg  holds$1;
    
    // Constant declarations
    localparam  perspective = 1'b1;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  shift = 16'h1;
    localparam  u0 = 16'hfffb;
    
    // Stub signals
    reg  [9:0] pos_x$address;
    wire  [15:0] pos_x$data;
    reg  [15:0] groups$address;
    wire  [31:0] groups$data;
    reg  [15:0] group_x$0$address;
    wire  [16:0] group_x$0$data;
    reg  [15:0] group_x$1$address;
    wire  [16:0] group_x$1$data;
    
    // Local signals
    reg  [15:0] chunk_ray;
    reg  [15:0] x0;
    
    // Sub module instances
    top$fetch$group$pos_x pos_x(
        .address(pos_x$address),
        .data(pos_x$data)
    );
    top$fetch$group$groups groups(
        .address(groups$address),
        .data(groups$data)
    );
    top$fetch$group$group_x$0 group_x$0(
        .address(group_x$0$address),
        .data(group_x$0$data)
    );
    top$fetch$group$group_x$1 group_x$1(
        .address(group_x$1$address),
        .data(group_x$1$data)
    );
    
    // Update code
    reg  [15:0] plane_pass;
    reg  [15:0] first_ray_pass;
    reg  [15:0] x$0_pass;
    reg  [15:0] x$1_pass;
    reg  holds$0_pass;
    reg  holds$1_pass;
    always @(*) begin
        pos_x$address = plane_count[('h0)+:(10)];
        groups$address = chunk;
        chunk_ray = chunk << shift;
        x0 = u0 + pos_x$data + chunk_ray;
        plane_pass = plane_count;
        first_ray_pass = chunk_ray;
        if (perspective) begin
            plane_pass = groups$data[('h0)+:(16)];
            first_ray_pass = groups$data[('h10)+:(16)];
        end
        group_x$0$address = chunk;
        x$0_pass = x0 + index$0;
        holds$0_pass = 1'b1;
        if (perspective) begin
            x$0_pass = group_x$0$data[('h0)+:(16)];
            holds$0_pass = group_x$0$data['h10];
        end
        group_x$1$address = chunk;
        x$1_pass = x0 + index$1;
        holds$1_pass = 1'b1;
        if (perspective) begin
            x$1_pass = group_x$1$data[('h0)+:(16)];
            holds$1_pass = group_x$1$data['h10];
        end
        plane = plane_pass;
        first_ray = first_ray_pass;
        x$0 = x$0_pass;
        x$1 = x$1_pass;
        holds$0 = holds$0_pass;
        holds$1 = holds$1_pass;
    end
    
endmodule // top$fetch$group
module top$fetch$group$group_x$0(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b11111111111111011;
      16'h1: data = 17'b11111111111111101;
      16'h2: data = 17'b11111111111111111;
      16'h3: data = 17'b10000000000000001;
      16'h4: data = 17'b10000000000000011;
      16'h5: data = 17'b10000000000000101;
      16'h6: data = 17'b10000000000000111;
      16'h7: data = 17'b10000000000001001;
      16'h8: data = 17'b11111111111111011;
      16'h9: data = 17'b11111111111111101;
      16'ha: data = 17'b11111111111111111;
      16'hb: data = 17'b10000000000000001;
      16'hc: data = 17'b10000000000000011;
      16'hd: data = 17'b10000000000000101;
      16'he: data = 17'b10000000000000111;
      16'hf: data = 17'b10000000000001001;
      16'h10: data = 17'b10000000000001011;
      16'h11: data = 17'b11111111111111011;
      16'h12: data = 17'b11111111111111101;
      16'h13: data = 17'b11111111111111111;
      16'h14: data = 17'b10000000000000001;
      16'h15: data = 17'b10000000000000011;
      16'h16: data = 17'b10000000000000101;
      16'h17: data = 17'b10000000000000111;
      16'h18: data = 17'b10000000000001010;
      16'h19: data = 17'b10000000000001100;
      16'h1a: data = 17'b11111111111111011;
      16'h1b: data = 17'b11111111111111101;
      16'h1c: data = 17'b11111111111111111;
      16'h1d: data = 17'b10000000000000001;
      16'h1e: data = 17'b10000000000000011;
      16'h1f: data = 17'b10000000000000101;
      16'h20: data = 17'b10000000000000111;
      16'h21: data = 17'b10000000000001001;
      16'h22: data = 17'b10000000000001011;
      16'h23: data = 17'b10000000000001101;
      16'h24: data = 17'b11111111111111011;
      16'h25: data = 17'b11111111111111101;
      16'h26: data = 17'b11111111111111111;
      16'h27: data = 17'b10000000000000010;
      16'h28: data = 17'b10000000000000100;
      16'h29: data = 17'b10000000000000111;
      16'h2a: data = 17'b10000000000001001;
      16'h2b: data = 17'b10000000000001100;
      16'h2c: data = 17'b10000000000001110;
      16'h2d: data = 17'b11111111111111011;
      16'h2e: data = 17'b11111111111111101;
      16'h2f: data = 17'b11111111111111111;
      16'h30: data = 17'b10000000000000001;
      16'h31: data = 17'b10000000000000011;
      16'h32: data = 17'b10000000000000101;
      16'h33: data = 17'b10000000000000111;
      16'h34: data = 17'b10000000000001001;
      16'h35: data = 17'b10000000000001011;
      16'h36: data = 17'b10000000000001101;
      16'h37: data = 17'b10000000000001111;
      16'h38: data = 17'b11111111111111100;
      16'h39: data = 17'b11111111111111110;
      16'h3a: data = 17'b10000000000000000;
      16'h3b: data = 17'b10000000000000011;
      16'h3c: data = 17'b10000000000000101;
      16'h3d: data = 17'b10000000000000111;
      16'h3e: data = 17'b10000000000001001;
      16'h3f: data = 17'b10000000000001011;
      16'h40: data = 17'b10000000000001110;
      16'h41: data = 17'b10000000000010000;
      16'h42: data = 17'b11111111111111100;
      16'h43: data = 17'b11111111111111111;
      16'h44: data = 17'b10000000000000010;
      16'h45: data = 17'b10000000000000100;
      16'h46: data = 17'b10000000000000110;
      16'h47: data = 17'b10000000000001001;
      16'h48: data = 17'b10000000000001100;
      16'h49: data = 17'b10000000000001111;
      16'h4a: data = 17'b10000000000010001;
      16'h4b: data = 17'b11111111111111100;
      16'h4c: data = 17'b11111111111111110;
      16'h4d: data = 17'b10000000000000001;
      16'h4e: data = 17'b10000000000000100;
      16'h4f: data = 17'b10000000000000111;
      16'h50: data = 17'b10000000000001010;
      16'h51: data = 17'b10000000000001101;
      16'h52: data = 17'b10000000000010000;
      16'h53: data = 17'b10000000000010011;
      16'h54: data = 17'b11111111111111100;
      16'h55: data = 17'b11111111111111110;
      16'h56: data = 17'b10000000000000001;
      16'h57: data = 17'b10000000000000100;
      16'h58: data = 17'b10000000000000110;
      16'h59: data = 17'b10000000000001001;
      16'h5a: data = 17'b10000000000001100;
      16'h5b: data = 17'b10000000000001111;
      16'h5c: data = 17'b10000000000010001;
      16'h5d: data = 17'b10000000000010100;
      16'h5e: data = 17'b11111111111111100;
      16'h5f: data = 17'b11111111111111110;
      16'h60: data = 17'b10000000000000000;
      16'h61: data = 17'b10000000000000011;
      16'h62: data = 17'b10000000000000101;
      16'h63: data = 17'b10000000000001000;
      16'h64: data = 17'b10000000000001011;
      16'h65: data = 17'b10000000000001101;
      16'h66: data = 17'b10000000000010000;
      16'h67: data = 17'b10000000000010010;
      16'h68: data = 17'b10000000000010101;
      16'h69: data = 17'b11111111111111101;
      16'h6a: data = 17'b10000000000000000;
      16'h6b: data = 17'b10000000000000010;
      16'h6c: data = 17'b10000000000000101;
      16'h6d: data = 17'b10000000000000111;
      16'h6e: data = 17'b10000000000001010;
      16'h6f: data = 17'b10000000000001100;
      16'h70: data = 17'b10000000000001111;
      16'h71: data = 17'b10000000000010001;
      16'h72: data = 17'b10000000000010011;
      16'h73: data = 17'b10000000000010110;
      16'h74: data = 17'b11111111111111101;
      16'h75: data = 17'b11111111111111111;
      16'h76: data = 17'b10000000000000010;
      16'h77: data = 17'b10000000000000100;
      16'h78: data = 17'b10000000000000110;
      16'h79: data = 17'b10000000000001001;
      16'h7a: data = 17'b10000000000001011;
      16'h7b: data = 17'b10000000000001101;
      16'h7c: data = 17'b10000000000010000;
      16'h7d: data = 17'b10000000000010010;
      16'h7e: data = 17'b10000000000010100;
      16'h7f: data = 17'b10000000000010111;
      16'h80: data = 17'b11111111111111101;
      16'h81: data = 17'b11111111111111111;
      16'h82: data = 17'b10000000000000001;
      16'h83: data = 17'b10000000000000100;
      16'h84: data = 17'b10000000000000110;
      16'h85: data = 17'b10000000000001000;
      16'h86: data = 17'b10000000000001010;
      16'h87: data = 17'b10000000000001101;
      16'h88: data = 17'b10000000000001111;
      16'h89: data = 17'b10000000000010001;
      16'h8a: data = 17'b10000000000010011;
      16'h8b: data = 17'b10000000000010101;
      16'h8c: data = 17'b10000000000011000;
      16'h8d: data = 17'b11111111111111101;
      16'h8e: data = 17'b11111111111111111;
      16'h8f: data = 17'b10000000000000001;
      16'h90: data = 17'b10000000000000011;
      16'h91: data = 17'b10000000000000101;
      16'h92: data = 17'b10000000000000111;
      16'h93: data = 17'b10000000000001010;
      16'h94: data = 17'b10000000000001100;
      16'h95: data = 17'b10000000000001110;
      16'h96: data = 17'b10000000000010000;
      16'h97: data = 17'b10000000000010010;
      16'h98: data = 17'b10000000000010100;
      16'h99: data = 17'b10000000000010110;
      16'h9a: data = 17'b10000000000011001;
      16'h9b: data = 17'b11111111111111101;
      16'h9c: data = 17'b11111111111111111;
      16'h9d: data = 17'b10000000000000001;
      16'h9e: data = 17'b10000000000000011;
      16'h9f: data = 17'b10000000000000101;
      16'ha0: data = 17'b10000000000000111;
      16'ha1: data = 17'b10000000000001001;
      16'ha2: data = 17'b10000000000001011;
      16'ha3: data = 17'b10000000000001101;
      16'ha4: data = 17'b10000000000001111;
      16'ha5: data = 17'b10000000000010001;
      16'ha6: data = 17'b10000000000010011;
      16'ha7: data = 17'b10000000000010101;
      16'ha8: data = 17'b10000000000010111;
      16'ha9: data = 17'b10000000000011010;
      16'haa: data = 17'b11111111111111110;
      16'hab: data = 17'b10000000000000000;
      16'hac: data = 17'b10000000000000010;
      16'had: data = 17'b10000000000000100;
      16'hae: data = 17'b10000000000000110;
      16'haf: data = 17'b10000000000001000;
      16'hb0: data = 17'b10000000000001010;
      16'hb1: data = 17'b10000000000001100;
      16'hb2: data = 17'b10000000000001110;
      16'hb3: data = 17'b10000000000010000;
      16'hb4: data = 17'b10000000000010010;
      16'hb5: data = 17'b10000000000010100;
      16'hb6: data = 17'b10000000000010110;
      16'hb7: data = 17'b10000000000011000;
      16'hb8: data = 17'b10000000000011010;
      16'hb9: data = 17'b10000000000011100;
      16'hba: data = 17'b11111111111111110;
      16'hbb: data = 17'b10000000000000000;
      16'hbc: data = 17'b10000000000000010;
      16'hbd: data = 17'b10000000000000100;
      16'hbe: data = 17'b10000000000000110;
      16'hbf: data = 17'b10000000000001000;
      16'hc0: data = 17'b10000000000001010;
      16'hc1: data = 17'b10000000000001100;
      16'hc2: data = 17'b10000000000001110;
      16'hc3: data = 17'b10000000000010000;
      16'hc4: data = 17'b10000000000010010;
      16'hc5: data = 17'b10000000000010100;
      16'hc6: data = 17'b10000000000010110;
      16'hc7: data = 17'b10000000000011001;
      16'hc8: data = 17'b10000000000011011;
      16'hc9: data = 17'b10000000000011101;
      16'hca: data = 17'b11111111111111110;
      16'hcb: data = 17'b10000000000000000;
      16'hcc: data = 17'b10000000000000010;
      16'hcd: data = 17'b10000000000000100;
      16'hce: data = 17'b10000000000000110;
      16'hcf: data = 17'b10000000000001001;
      16'hd0: data = 17'b10000000000001011;
      16'hd1: data = 17'b10000000000001101;
      16'hd2: data = 17'b10000000000001111;
      16'hd3: data = 17'b10000000000010001;
      16'hd4: data = 17'b10000000000010011;
      16'hd5: data = 17'b10000000000010101;
      16'hd6: data = 17'b10000000000010111;
      16'hd7: data = 17'b10000000000011010;
      16'hd8: data = 17'b10000000000011100;
      16'hd9: data = 17'b10000000000011110;
      16'hda: data = 17'b11111111111111110;
      16'hdb: data = 17'b10000000000000000;
      16'hdc: data = 17'b10000000000000010;
      16'hdd: data = 17'b10000000000000101;
      16'hde: data = 17'b10000000000000111;
      16'hdf: data = 17'b10000000000001001;
      16'he0: data = 17'b10000000000001011;
      16'he1: data = 17'b10000000000001101;
      16'he2: data = 17'b10000000000010000;
      16'he3: data = 17'b10000000000010010;
      16'he4: data = 17'b10000000000010100;
      16'he5: data = 17'b10000000000010110;
      16'he6: data = 17'b10000000000011000;
      16'he7: data = 17'b10000000000011011;
      16'he8: data = 17'b10000000000011101;
      16'he9: data = 17'b10000000000011111;
      default: data = 17'b0;
    endcase
            
endmodule // top$fetch$group$group_x$0
module top$fetch$group$group_x$1(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b11111111111111100;
      16'h1: data = 17'b11111111111111110;
      16'h2: data = 17'b10000000000000000;
      16'h3: data = 17'b10000000000000010;
      16'h4: data = 17'b10000000000000100;
      16'h5: data = 17'b10000000000000110;
      16'h6: data = 17'b10000000000001000;
      16'h7: data = 17'b10000000000001010;
      16'h8: data = 17'b11111111111111100;
      16'h9: data = 17'b11111111111111110;
      16'ha: data = 17'b10000000000000000;
      16'hb: data = 17'b10000000000000010;
      16'hc: data = 17'b10000000000000100;
      16'hd: data = 17'b10000000000000110;
      16'he: data = 17'b0;
      16'hf: data = 17'b10000000000001010;
      16'h10: data = 17'b0;
      16'h11: data = 17'b11111111111111100;
      16'h12: data = 17'b11111111111111110;
      16'h13: data = 17'b0;
      16'h14: data = 17'b10000000000000010;
      16'h15: data = 17'b10000000000000100;
      16'h16: data = 17'b10000000000000110;
      16'h17: data = 17'b10000000000001000;
      16'h18: data = 17'b10000000000001011;
      16'h19: data = 17'b0;
      16'h1a: data = 17'b11111111111111100;
      16'h1b: data = 17'b0;
      16'h1c: data = 17'b10000000000000000;
      16'h1d: data = 17'b10000000000000010;
      16'h1e: data = 17'b0;
      16'h1f: data = 17'b10000000000000110;
      16'h20: data = 17'b10000000000001000;
      16'h21: data = 17'b0;
      16'h22: data = 17'b10000000000001100;
      16'h23: data = 17'b0;
      16'h24: data = 17'b0;
      16'h25: data = 17'b11111111111111110;
      16'h26: data = 17'b10000000000000000;
      16'h27: data = 17'b10000000000000011;
      16'h28: data = 17'b10000000000000101;
      16'h29: data = 17'b10000000000001000;
      16'h2a: data = 17'b10000000000001010;
      16'h2b: data = 17'b10000000000001101;
      16'h2c: data = 17'b0;
      16'h2d: data = 17'b0;
      16'h2e: data = 17'b11111111111111110;
      16'h2f: data = 17'b0;
      16'h30: data = 17'b10000000000000010;
      16'h31: data = 17'b0;
      16'h32: data = 17'b10000000000000110;
      16'h33: data = 17'b0;
      16'h34: data = 17'b10000000000001010;
      16'h35: data = 17'b0;
      16'h36: data = 17'b10000000000001110;
      16'h37: data = 17'b0;
      16'h38: data = 17'b11111111111111101;
      16'h39: data = 17'b0;
      16'h3a: data = 17'b10000000000000001;
      16'h3b: data = 17'b10000000000000100;
      16'h3c: data = 17'b0;
      16'h3d: data = 17'b10000000000001000;
      16'h3e: data = 17'b0;
      16'h3f: data = 17'b10000000000001100;
      16'h40: data = 17'b10000000000001111;
      16'h41: data = 17'b0;
      16'h42: data = 17'b11111111111111101;
      16'h43: data = 17'b10000000000000000;
      16'h44: data = 17'b10000000000000011;
      16'h45: data = 17'b0;
      16'h46: data = 17'b10000000000000111;
      16'h47: data = 17'b10000000000001010;
      16'h48: data = 17'b10000000000001101;
      16'h49: data = 17'b10000000000010000;
      16'h4a: data = 17'b0;
      16'h4b: data = 17'b0;
      16'h4c: data = 17'b11111111111111111;
      16'h4d: data = 17'b10000000000000010;
      16'h4e: data = 17'b10000000000000101;
      16'h4f: data = 17'b10000000000001000;
      16'h50: data = 17'b10000000000001011;
      16'h51: data = 17'b10000000000001110;
      16'h52: data = 17'b10000000000010001;
      16'h53: data = 17'b0;
      16'h54: data = 17'b0;
      16'h55: data = 17'b11111111111111111;
      16'h56: data = 17'b10000000000000010;
      16'h57: data = 17'b0;
      16'h58: data = 17'b10000000000000111;
      16'h59: data = 17'b10000000000001010;
      16'h5a: data = 17'b10000000000001101;
      16'h5b: data = 17'b0;
      16'h5c: data = 17'b10000000000010010;
      16'h5d: data = 17'b0;
      16'h5e: data = 17'b0;
      16'h5f: data = 17'b0;
      16'h60: data = 17'b10000000000000001;
      16'h61: data = 17'b0;
      16'h62: data = 17'b10000000000000110;
      16'h63: data = 17'b10000000000001001;
      16'h64: data = 17'b0;
      16'h65: data = 17'b10000000000001110;
      16'h66: data = 17'b0;
      16'h67: data = 17'b10000000000010011;
      16'h68: data = 17'b0;
      16'h69: data = 17'b11111111111111110;
      16'h6a: data = 17'b0;
      16'h6b: data = 17'b10000000000000011;
      16'h6c: data = 17'b0;
      16'h6d: data = 17'b10000000000001000;
      16'h6e: data = 17'b0;
      16'h6f: data = 17'b10000000000001101;
      16'h70: data = 17'b0;
      16'h71: data = 17'b0;
      16'h72: data = 17'b10000000000010100;
      16'h73: data = 17'b0;
      16'h74: data = 17'b0;
      16'h75: data = 17'b10000000000000000;
      16'h76: data = 17'b0;
      16'h77: data = 17'b0;
      16'h78: data = 17'b10000000000000111;
      16'h79: data = 17'b0;
      16'h7a: data = 17'b0;
      16'h7b: data = 17'b10000000000001110;
      16'h7c: data = 17'b0;
      16'h7d: data = 17'b0;
      16'h7e: data = 17'b10000000000010101;
      16'h7f: data = 17'b0;
      16'h80: data = 17'b0;
      16'h81: data = 17'b0;
      16'h82: data = 17'b10000000000000010;
      16'h83: data = 17'b0;
      16'h84: data = 17'b0;
      16'h85: data = 17'b0;
      16'h86: data = 17'b10000000000001011;
      16'h87: data = 17'b0;
      16'h88: data = 17'b0;
      16'h89: data = 17'b0;
      16'h8a: data = 17'b0;
      16'h8b: data = 17'b10000000000010110;
      16'h8c: data = 17'b0;
      16'h8d: data = 17'b0;
      16'h8e: data = 17'b0;
      16'h8f: data = 17'b0;
      16'h90: data = 17'b0;
      16'h91: data = 17'b0;
      16'h92: data = 17'b10000000000001000;
      16'h93: data = 17'b0;
      16'h94: data = 17'b0;
      16'h95: data = 17'b0;
      16'h96: data = 17'b0;
      16'h97: data = 17'b0;
      16'h98: data = 17'b0;
      16'h99: data = 17'b10000000000010111;
      16'h9a: data = 17'b0;
      16'h9b: data = 17'b0;
      16'h9c: data = 17'b0;
      16'h9d: data = 17'b0;
      16'h9e: data = 17'b0;
      16'h9f: data = 17'b0;
      16'ha0: data = 17'b0;
      16'ha1: data = 17'b0;
      16'ha2: data = 17'b0;
      16'ha3: data = 17'b0;
      16'ha4: data = 17'b0;
      16'ha5: data = 17'b0;
      16'ha6: data = 17'b0;
      16'ha7: data = 17'b0;
      16'ha8: data = 17'b10000000000011000;
      16'ha9: data = 17'b0;
      16'haa: data = 17'b0;
      16'hab: data = 17'b0;
      16'hac: data = 17'b0;
      16'had: data = 17'b0;
      16'hae: data = 17'b0;
      16'haf: data = 17'b0;
      16'hb0: data = 17'b0;
      16'hb1: data = 17'b0;
      16'hb2: data = 17'b0;
      16'hb3: data = 17'b0;
      16'hb4: data = 17'b0;
      16'hb5: data = 17'b0;
      16'hb6: data = 17'b0;
      16'hb7: data = 17'b0;
      16'hb8: data = 17'b0;
      16'hb9: data = 17'b0;
      16'hba: data = 17'b0;
      16'hbb: data = 17'b0;
      16'hbc: data = 17'b0;
      16'hbd: data = 17'b0;
      16'hbe: data = 17'b0;
      16'hbf: data = 17'b0;
      16'hc0: data = 17'b0;
      16'hc1: data = 17'b0;
      16'hc2: data = 17'b0;
      16'hc3: data = 17'b0;
      16'hc4: data = 17'b0;
      16'hc5: data = 17'b0;
      16'hc6: data = 17'b0;
      16'hc7: data = 17'b0;
      16'hc8: data = 17'b0;
      16'hc9: data = 17'b0;
      16'hca: data = 17'b0;
      16'hcb: data = 17'b0;
      16'hcc: data = 17'b0;
      16'hcd: data = 17'b0;
      16'hce: data = 17'b0;
      16'hcf: data = 17'b0;
      16'hd0: data = 17'b0;
      16'hd1: data = 17'b0;
      16'hd2: data = 17'b0;
      16'hd3: data = 17'b0;
      16'hd4: data = 17'b0;
      16'hd5: data = 17'b0;
      16'hd6: data = 17'b0;
      16'hd7: data = 17'b0;
      16'hd8: data = 17'b0;
      16'hd9: data = 17'b0;
      16'hda: data = 17'b0;
      16'hdb: data = 17'b0;
      16'hdc: data = 17'b0;
      16'hdd: data = 17'b0;
      16'hde: data = 17'b0;
      16'hdf: data = 17'b0;
      16'he0: data = 17'b0;
      16'he1: data = 17'b0;
      16'he2: data = 17'b0;
      16'he3: data = 17'b0;
      16'he4: data = 17'b0;
      16'he5: data = 17'b0;
      16'he6: data = 17'b0;
      16'he7: data = 17'b0;
      16'he8: data = 17'b0;
      16'he9: data = 17'b0;
      default: data = 17'b0;
    endcase
            
endmodule // top$fetch$group$group_x$1
module top$fetch$group$groups(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 'h0;
      16'h1: data = 'h20000;
      16'h2: data = 'h40000;
      16'h3: data = 'h60000;
      16'h4: data = 'h80000;
      16'h5: data = 'ha0000;
      16'h6: data = 'hc0000;
      16'h7: data = 'he0000;
      16'h8: data = 'h1;
      16'h9: data = 'h20001;
      16'ha: data = 'h40001;
      16'hb: data = 'h60001;
      16'hc: data = 'h80001;
      16'hd: data = 'ha0001;
      16'he: data = 'hc0001;
      16'hf: data = 'hd0001;
      16'h10: data = 'hf0001;
      16'h11: data = 'h2;
      16'h12: data = 'h20002;
      16'h13: data = 'h40002;
      16'h14: data = 'h50002;
      16'h15: data = 'h70002;
      16'h16: data = 'h90002;
      16'h17: data = 'hb0002;
      16'h18: data = 'hd0002;
      16'h19: data = 'hf0002;
      16'h1a: data = 'h3;
      16'h1b: data = 'h20003;
      16'h1c: data = 'h30003;
      16'h1d: data = 'h50003;
      16'h1e: data = 'h70003;
      16'h1f: data = 'h80003;
      16'h20: data = 'ha0003;
      16'h21: data = 'hc0003;
      16'h22: data = 'hd0003;
      16'h23: data = 'hf0003;
      16'h24: data = 'h4;
      16'h25: data = 'h10004;
      16'h26: data = 'h30004;
      16'h27: data = 'h50004;
      16'h28: data = 'h70004;
      16'h29: data = 'h90004;
      16'h2a: data = 'hb0004;
      16'h2b: data = 'hd0004;
      16'h2c: data = 'hf0004;
      16'h2d: data = 'h5;
      16'h2e: data = 'h10005;
      16'h2f: data = 'h30005;
      16'h30: data = 'h40005;
      16'h31: data = 'h60005;
      16'h32: data = 'h70005;
      16'h33: data = 'h90005;
      16'h34: data = 'ha0005;
      16'h35: data = 'hc0005;
      16'h36: data = 'hd0005;
      16'h37: data = 'hf0005;
      16'h38: data = 'h6;
      16'h39: data = 'h20006;
      16'h3a: data = 'h30006;
      16'h3b: data = 'h50006;
      16'h3c: data = 'h70006;
      16'h3d: data = 'h80006;
      16'h3e: data = 'ha0006;
      16'h3f: data = 'hb0006;
      16'h40: data = 'hd0006;
      16'h41: data = 'hf0006;
      16'h42: data = 'h7;
      16'h43: data = 'h20007;
      16'h44: data = 'h40007;
      16'h45: data = 'h60007;
      16'h46: data = 'h70007;
      16'h47: data = 'h90007;
      16'h48: data = 'hb0007;
      16'h49: data = 'hd0007;
      16'h4a: data = 'hf0007;
      16'h4b: data = 'h8;
      16'h4c: data = 'h10008;
      16'h4d: data = 'h30008;
      16'h4e: data = 'h50008;
      16'h4f: data = 'h70008;
      16'h50: data = 'h90008;
      16'h51: data = 'hb0008;
      16'h52: data = 'hd0008;
      16'h53: data = 'hf0008;
      16'h54: data = 'h9;
      16'h55: data = 'h10009;
      16'h56: data = 'h30009;
      16'h57: data = 'h50009;
      16'h58: data = 'h60009;
      16'h59: data = 'h80009;
      16'h5a: data = 'ha0009;
      16'h5b: data = 'hc0009;
      16'h5c: data = 'hd0009;
      16'h5d: data = 'hf0009;
      16'h5e: data = 'ha;
      16'h5f: data = 'h1000a;
      16'h60: data = 'h2000a;
      16'h61: data = 'h4000a;
      16'h62: data = 'h5000a;
      16'h63: data = 'h7000a;
      16'h64: data = 'h9000a;
      16'h65: data = 'ha000a;
      16'h66: data = 'hc000a;
      16'h67: data = 'hd000a;
      16'h68: data = 'hf000a;
      16'h69: data = 'hb;
      16'h6a: data = 'h2000b;
      16'h6b: data = 'h3000b;
      16'h6c: data = 'h5000b;
      16'h6d: data = 'h6000b;
      16'h6e: data = 'h8000b;
      16'h6f: data = 'h9000b;
      16'h70: data = 'hb000b;
      16'h71: data = 'hc000b;
      16'h72: data = 'hd000b;
      16'h73: data = 'hf000b;
      16'h74: data = 'hc;
      16'h75: data = 'h1000c;
      16'h76: data = 'h3000c;
      16'h77: data = 'h4000c;
      16'h78: data = 'h5000c;
      16'h79: data = 'h7000c;
      16'h7a: data = 'h8000c;
      16'h7b: data = 'h9000c;
      16'h7c: data = 'hb000c;
      16'h7d: data = 'hc000c;
      16'h7e: data = 'hd000c;
      16'h7f: data = 'hf000c;
      16'h80: data = 'hd;
      16'h81: data = 'h1000d;
      16'h82: data = 'h2000d;
      16'h83: data = 'h4000d;
      16'h84: data = 'h5000d;
      16'h85: data = 'h6000d;
      16'h86: data = 'h7000d;
      16'h87: data = 'h9000d;
      16'h88: data = 'ha000d;
      16'h89: data = 'hb000d;
      16'h8a: data = 'hc000d;
      16'h8b: data = 'hd000d;
      16'h8c: data = 'hf000d;
      16'h8d: data = 'he;
      16'h8e: data = 'h1000e;
      16'h8f: data = 'h2000e;
      16'h90: data = 'h3000e;
      16'h91: data = 'h4000e;
      16'h92: data = 'h5000e;
      16'h93: data = 'h7000e;
      16'h94: data = 'h8000e;
      16'h95: data = 'h9000e;
      16'h96: data = 'ha000e;
      16'h97: data = 'hb000e;
      16'h98: data = 'hc000e;
      16'h99: data = 'hd000e;
      16'h9a: data = 'hf000e;
      16'h9b: data = 'hf;
      16'h9c: data = 'h1000f;
      16'h9d: data = 'h2000f;
      16'h9e: data = 'h3000f;
      16'h9f: data = 'h4000f;
      16'ha0: data = 'h5000f;
      16'ha1: data = 'h6000f;
      16'ha2: data = 'h7000f;
      16'ha3: data = 'h8000f;
      16'ha4: data = 'h9000f;
      16'ha5: data = 'ha000f;
      16'ha6: data = 'hb000f;
      16'ha7: data = 'hc000f;
      16'ha8: data = 'hd000f;
      16'ha9: data = 'hf000f;
      16'haa: data = 'h10;
      16'hab: data = 'h10010;
      16'hac: data = 'h20010;
      16'had: data = 'h30010;
      16'hae: data = 'h40010;
      16'haf: data = 'h50010;
      16'hb0: data = 'h60010;
      16'hb1: data = 'h70010;
      16'hb2: data = 'h80010;
      16'hb3: data = 'h90010;
      16'hb4: data = 'ha0010;
      16'hb5: data = 'hb0010;
      16'hb6: data = 'hc0010;
      16'hb7: data = 'hd0010;
      16'hb8: data = 'he0010;
      16'hb9: data = 'hf0010;
      16'hba: data = 'h11;
      16'hbb: data = 'h10011;
      16'hbc: data = 'h20011;
      16'hbd: data = 'h30011;
      16'hbe: data = 'h40011;
      16'hbf: data = 'h50011;
      16'hc0: data = 'h60011;
      16'hc1: data = 'h70011;
      16'hc2: data = 'h80011;
      16'hc3: data = 'h90011;
      16'hc4: data = 'ha0011;
      16'hc5: data = 'hb0011;
      16'hc6: data = 'hc0011;
      16'hc7: data = 'hd0011;
      16'hc8: data = 'he0011;
      16'hc9: data = 'hf0011;
      16'hca: data = 'h12;
      16'hcb: data = 'h10012;
      16'hcc: data = 'h20012;
      16'hcd: data = 'h30012;
      16'hce: data = 'h40012;
      16'hcf: data = 'h50012;
      16'hd0: data = 'h60012;
      16'hd1: data = 'h70012;
      16'hd2: data = 'h80012;
      16'hd3: data = 'h90012;
      16'hd4: data = 'ha0012;
      16'hd5: data = 'hb0012;
      16'hd6: data = 'hc0012;
      16'hd7: data = 'hd0012;
      16'hd8: data = 'he0012;
      16'hd9: data = 'hf0012;
      16'hda: data = 'h13;
      16'hdb: data = 'h10013;
      16'hdc: data = 'h20013;
      16'hdd: data = 'h30013;
      16'hde: data = 'h40013;
      16'hdf: data = 'h50013;
      16'he0: data = 'h60013;
      16'he1: data = 'h70013;
      16'he2: data = 'h80013;
      16'he3: data = 'h90013;
      16'he4: data = 'ha0013;
      16'he5: data = 'hb0013;
      16'he6: data = 'hc0013;
      16'he7: data = 'hd0013;
      16'he8: data = 'he0013;
      16'he9: data = 'hf0013;
      default: data = 'h0;
    endcase
            
endmodule // top$fetch$group$groups
module top$fetch$group$pos_x(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
      
      default: data = 16'h0;
    endcase
            
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
    reg [15:0] mem[2879:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[11:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[11:0]] <= write_data;
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
    reg [15:0] mem[2879:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[11:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[11:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$1
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
module top$fetch$plane_q(d,q,clock);
    
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
          
endmodule // top$fetch$plane_q
module top$fetch$pos_y(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h0;
      'h1: data = 16'h0;
      'h2: data = 16'h0;
      'h3: data = 16'h1;
      'h4: data = 16'h1;
      'h5: data = 16'h1;
      'h6: data = 16'h2;
      'h7: data = 16'h2;
      'h8: data = 16'h3;
      'h9: data = 16'h3;
      'ha: data = 16'h3;
      'hb: data = 16'h4;
      'hc: data = 16'h4;
      'hd: data = 16'h4;
      'he: data = 16'h5;
      'hf: data = 16'h5;
      'h10: data = 16'h6;
      'h11: data = 16'h6;
      'h12: data = 16'h6;
      'h13: data = 16'h7;
      'h14: data = 16'h7;
      'h15: data = 16'h0;
      'h16: data = 16'h0;
      'h17: data = 16'h0;
      'h18: data = 16'h1;
      'h19: data = 16'h1;
      'h1a: data = 16'h2;
      'h1b: data = 16'h2;
      'h1c: data = 16'h3;
      'h1d: data = 16'h3;
      'h1e: data = 16'h3;
      'h1f: data = 16'h4;
      'h20: data = 16'h4;
      'h21: data = 16'h5;
      'h22: data = 16'h5;
      'h23: data = 16'h6;
      'h24: data = 16'h6;
      'h25: data = 16'h7;
      'h26: data = 16'h7;
      'h27: data = 16'h7;
      'h28: data = 16'h8;
      'h29: data = 16'h8;
      'h2a: data = 16'h0;
      'h2b: data = 16'h0;
      'h2c: data = 16'h1;
      'h2d: data = 16'h1;
      'h2e: data = 16'h2;
      'h2f: data = 16'h2;
      'h30: data = 16'h3;
      'h31: data = 16'h3;
      'h32: data = 16'h4;
      'h33: data = 16'h4;
      'h34: data = 16'h5;
      'h35: data = 16'h5;
      'h36: data = 16'h6;
      'h37: data = 16'h6;
      'h38: data = 16'h7;
      'h39: data = 16'h7;
      'h3a: data = 16'h8;
      'h3b: data = 16'h8;
      'h3c: data = 16'h9;
      'h3d: data = 16'h9;
      'h3e: data = 16'ha;
      'h3f: data = 16'h0;
      'h40: data = 16'h0;
      'h41: data = 16'h1;
      'h42: data = 16'h1;
      'h43: data = 16'h2;
      'h44: data = 16'h2;
      'h45: data = 16'h3;
      'h46: data = 16'h3;
      'h47: data = 16'h4;
      'h48: data = 16'h5;
      'h49: data = 16'h5;
      'h4a: data = 16'h6;
      'h4b: data = 16'h6;
      'h4c: data = 16'h7;
      'h4d: data = 16'h7;
      'h4e: data = 16'h8;
      'h4f: data = 16'h9;
      'h50: data = 16'h9;
      'h51: data = 16'ha;
      'h52: data = 16'ha;
      'h53: data = 16'hb;
      'h54: data = 16'h0;
      'h55: data = 16'h0;
      'h56: data = 16'h1;
      'h57: data = 16'h1;
      'h58: data = 16'h2;
      'h59: data = 16'h3;
      'h5a: data = 16'h3;
      'h5b: data = 16'h4;
      'h5c: data = 16'h5;
      'h5d: data = 16'h5;
      'h5e: data = 16'h6;
      'h5f: data = 16'h6;
      'h60: data = 16'h7;
      'h61: data = 16'h8;
      'h62: data = 16'h8;
      'h63: data = 16'h9;
      'h64: data = 16'ha;
      'h65: data = 16'ha;
      'h66: data = 16'hb;
      'h67: data = 16'hb;
      'h68: data = 16'hc;
      'h69: data = 16'h0;
      'h6a: data = 16'h0;
      'h6b: data = 16'h1;
      'h6c: data = 16'h2;
      'h6d: data = 16'h2;
      'h6e: data = 16'h3;
      'h6f: data = 16'h4;
      'h70: data = 16'h4;
      'h71: data = 16'h5;
      'h72: data = 16'h6;
      'h73: data = 16'h6;
      'h74: data = 16'h7;
      'h75: data = 16'h8;
      'h76: data = 16'h8;
      'h77: data = 16'h9;
      'h78: data = 16'ha;
      'h79: data = 16'hb;
      'h7a: data = 16'hb;
      'h7b: data = 16'hc;
      'h7c: data = 16'hd;
      'h7d: data = 16'hd;
      'h7e: data = 16'h0;
      'h7f: data = 16'h0;
      'h80: data = 16'h1;
      'h81: data = 16'h2;
      'h82: data = 16'h3;
      'h83: data = 16'h3;
      'h84: data = 16'h4;
      'h85: data = 16'h5;
      'h86: data = 16'h6;
      'h87: data = 16'h6;
      'h88: data = 16'h7;
      'h89: data = 16'h8;
      'h8a: data = 16'h9;
      'h8b: data = 16'h9;
      'h8c: data = 16'ha;
      'h8d: data = 16'hb;
      'h8e: data = 16'hc;
      'h8f: data = 16'hc;
      'h90: data = 16'hd;
      'h91: data = 16'he;
      'h92: data = 16'hf;
      'h93: data = 16'h0;
      'h94: data = 16'h0;
      'h95: data = 16'h1;
      'h96: data = 16'h2;
      'h97: data = 16'h3;
      'h98: data = 16'h4;
      'h99: data = 16'h4;
      'h9a: data = 16'h5;
      'h9b: data = 16'h6;
      'h9c: data = 16'h7;
      'h9d: data = 16'h8;
      'h9e: data = 16'h8;
      'h9f: data = 16'h9;
      'ha0: data = 16'ha;
      'ha1: data = 16'hb;
      'ha2: data = 16'hc;
      'ha3: data = 16'hd;
      'ha4: data = 16'hd;
      'ha5: data = 16'he;
      'ha6: data = 16'hf;
      'ha7: data = 16'h10;
      'ha8: data = 16'h0;
      'ha9: data = 16'h0;
      'haa: data = 16'h1;
      'hab: data = 16'h2;
      'hac: data = 16'h3;
      'had: data = 16'h4;
      'hae: data = 16'h5;
      'haf: data = 16'h6;
      'hb0: data = 16'h7;
      'hb1: data = 16'h7;
      'hb2: data = 16'h8;
      'hb3: data = 16'h9;
      'hb4: data = 16'ha;
      'hb5: data = 16'hb;
      'hb6: data = 16'hc;
      'hb7: data = 16'hd;
      'hb8: data = 16'he;
      'hb9: data = 16'he;
      'hba: data = 16'hf;
      'hbb: data = 16'h10;
      'hbc: data = 16'h11;
      'hbd: data = 16'h0;
      'hbe: data = 16'h0;
      'hbf: data = 16'h1;
      'hc0: data = 16'h2;
      'hc1: data = 16'h3;
      'hc2: data = 16'h4;
      'hc3: data = 16'h5;
      'hc4: data = 16'h6;
      'hc5: data = 16'h7;
      'hc6: data = 16'h8;
      'hc7: data = 16'h9;
      'hc8: data = 16'ha;
      'hc9: data = 16'hb;
      'hca: data = 16'hc;
      'hcb: data = 16'hd;
      'hcc: data = 16'he;
      'hcd: data = 16'hf;
      'hce: data = 16'hf;
      'hcf: data = 16'h10;
      'hd0: data = 16'h11;
      'hd1: data = 16'h12;
      'hd2: data = 16'h0;
      'hd3: data = 16'h1;
      'hd4: data = 16'h2;
      'hd5: data = 16'h3;
      'hd6: data = 16'h4;
      'hd7: data = 16'h5;
      'hd8: data = 16'h6;
      'hd9: data = 16'h7;
      'hda: data = 16'h8;
      'hdb: data = 16'h9;
      'hdc: data = 16'ha;
      'hdd: data = 16'hb;
      'hde: data = 16'hc;
      'hdf: data = 16'hd;
      'he0: data = 16'he;
      'he1: data = 16'hf;
      'he2: data = 16'h10;
      'he3: data = 16'h11;
      'he4: data = 16'h12;
      'he5: data = 16'h13;
      'he6: data = 16'h14;
      'he7: data = 16'h0;
      'he8: data = 16'h1;
      'he9: data = 16'h2;
      'hea: data = 16'h3;
      'heb: data = 16'h4;
      'hec: data = 16'h5;
      'hed: data = 16'h6;
      'hee: data = 16'h7;
      'hef: data = 16'h8;
      'hf0: data = 16'h9;
      'hf1: data = 16'ha;
      'hf2: data = 16'hb;
      'hf3: data = 16'hc;
      'hf4: data = 16'hd;
      'hf5: data = 16'he;
      'hf6: data = 16'hf;
      'hf7: data = 16'h11;
      'hf8: data = 16'h12;
      'hf9: data = 16'h13;
      'hfa: data = 16'h14;
      'hfb: data = 16'h15;
      'hfc: data = 16'h0;
      'hfd: data = 16'h1;
      'hfe: data = 16'h2;
      'hff: data = 16'h3;
      'h100: data = 16'h4;
      'h101: data = 16'h5;
      'h102: data = 16'h6;
      'h103: data = 16'h7;
      'h104: data = 16'h9;
      'h105: data = 16'ha;
      'h106: data = 16'hb;
      'h107: data = 16'hc;
      'h108: data = 16'hd;
      'h109: data = 16'he;
      'h10a: data = 16'hf;
      'h10b: data = 16'h10;
      'h10c: data = 16'h12;
      'h10d: data = 16'h13;
      'h10e: data = 16'h14;
      'h10f: data = 16'h15;
      'h110: data = 16'h16;
      default: data = 16'h0;
    endcase
            
endmodule // top$fetch$pos_y
module top$fetch$ray_q$0(d,q,clock);
    
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
          
endmodule // top$fetch$ray_q$0
module top$fetch$ray_q$1(d,q,clock);
    
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
          
endmodule // top$fetch$ray_q$1
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
module top$fetch$schedule(clock,start,writing,plane,chunk,period,write_buffer,reading,ray,segment,cur_buffer,next_buffer);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    output reg  writing;
    output reg  [15:0] plane;
    output reg  [15:0] chunk;
    output reg  [15:0] period;
    output reg  [1:0] write_buffer;
    output reg  reading;
    output reg  [15:0] ray;
    output reg  [15:0] segment;
    output reg  [1:0] cur_buffer;
    output reg  [1:0] next_buffer;
    
    // Constant declarations
    localparam  last_tick = 16'hea;
    localparam  last_period = 16'hd;
    localparam  last_write_period = 16'hc;
    localparam  last_plane = 16'h0;
    localparam  last_chunk = 16'he9;
    localparam  last_ray = 16'hf;
    localparam  last_segment = 16'h9;
    localparam  first_read_period = 16'h2;
    
    // Stub signals
    reg  active$d;
    wire  active$q;
    reg  active$clock;
    reg  [15:0] tick$d;
    wire  [15:0] tick$q;
    reg  tick$clock;
    reg  [15:0] period_q$d;
    wire  [15:0] period_q$q;
    reg  period_q$clock;
    reg  [15:0] plane_q$d;
    wire  [15:0] plane_q$q;
    reg  plane_q$clock;
    reg  [15:0] chunk_q$d;
    wire  [15:0] chunk_q$q;
    reg  chunk_q$clock;
    reg  [15:0] ray_q$d;
    wire  [15:0] ray_q$q;
    reg  ray_q$clock;
    reg  [15:0] segment_q$d;
    wire  [15:0] segment_q$q;
    reg  segment_q$clock;
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
    
    // Sub module instances
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
        written$d = written$q;
        read$d = read$q;
        w_q$d = w_q$q;
        c_q$d = c_q$q;
        n_q$d = n_q$q;
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
            written$d = 1'b0;
            read$d = 1'b0;
            w_q$d = 'h0;
            n_q$d = 'h2;
            c_q$d = 'h1;
        end
        plane = plane_q$q;
        chunk = chunk_q$q;
        period = period_q$q;
        write_buffer = w_q$q;
        ray = ray_q$q;
        segment = segment_q$q;
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
