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
    localparam  external = 1'b1;
    localparam  row_stride = 16'h0;
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
    localparam  n_x = 16'h6e;
    localparam  n_y = 16'h100;
    localparam  n_k = 16'h100;
    localparam  row_words = 16'h37;
    localparam  plane_words = 16'h3700;
    localparam  v0 = 16'hff63;
    localparam  rays = 16'hcf;
    localparam  segments = 16'h80;
    
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
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
    localparam  perspective = 1'b0;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  shift = 16'h1;
    localparam  u0 = 16'hfffe;
    
    // Stub signals
    reg  [9:0] pos_x$address;
    wire  [15:0] pos_x$data;
    reg  [15:0] groups$address;
    wire  [31:0] groups$data = 'h0;
    reg  [15:0] group_x$0$address;
    wire  [16:0] group_x$0$data = 'h0;
    reg  [15:0] group_x$1$address;
    wire  [16:0] group_x$1$data = 'h0;
    
    // Local signals
    reg  [15:0] chunk_ray;
    reg  [15:0] x0;
    
    // Sub module instances
    top$fetch$group$pos_x pos_x(
        .address(pos_x$address),
        .data(pos_x$data)
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
module top$fetch$group$pos_x(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        10'b0: data = 16'h0;
      10'b1: data = 16'hffff;
      10'b10: data = 16'hffff;
      10'b11: data = 16'hfffe;
      10'b100: data = 16'hfffe;
      10'b101: data = 16'hfffe;
      10'b110: data = 16'hfffd;
      10'b111: data = 16'hfffd;
      10'b1000: data = 16'hfffd;
      10'b1001: data = 16'hfffc;
      10'b1010: data = 16'hfffc;
      10'b1011: data = 16'hfffc;
      10'b1100: data = 16'hfffb;
      10'b1101: data = 16'hfffb;
      10'b1110: data = 16'hfffa;
      10'b1111: data = 16'hfffa;
      10'b10000: data = 16'hfffa;
      10'b10001: data = 16'hfff9;
      10'b10010: data = 16'hfff9;
      10'b10011: data = 16'hfff9;
      10'b10100: data = 16'hfff8;
      10'b10101: data = 16'hfff8;
      10'b10110: data = 16'hfff8;
      10'b10111: data = 16'hfff7;
      10'b11000: data = 16'hfff7;
      10'b11001: data = 16'hfff6;
      10'b11010: data = 16'hfff6;
      10'b11011: data = 16'hfff6;
      10'b11100: data = 16'hfff5;
      10'b11101: data = 16'hfff5;
      10'b11110: data = 16'hfff5;
      10'b11111: data = 16'hfff4;
      10'b100000: data = 16'hfff4;
      10'b100001: data = 16'hfff4;
      10'b100010: data = 16'hfff3;
      10'b100011: data = 16'hfff3;
      10'b100100: data = 16'hfff2;
      10'b100101: data = 16'hfff2;
      10'b100110: data = 16'hfff2;
      10'b100111: data = 16'hfff1;
      10'b101000: data = 16'hfff1;
      10'b101001: data = 16'hfff1;
      10'b101010: data = 16'hfff0;
      10'b101011: data = 16'hfff0;
      10'b101100: data = 16'hfff0;
      10'b101101: data = 16'hffef;
      10'b101110: data = 16'hffef;
      10'b101111: data = 16'hffee;
      10'b110000: data = 16'hffee;
      10'b110001: data = 16'hffee;
      10'b110010: data = 16'hffed;
      10'b110011: data = 16'hffed;
      10'b110100: data = 16'hffed;
      10'b110101: data = 16'hffec;
      10'b110110: data = 16'hffec;
      10'b110111: data = 16'hffec;
      10'b111000: data = 16'hffeb;
      10'b111001: data = 16'hffeb;
      10'b111010: data = 16'hffea;
      10'b111011: data = 16'hffea;
      10'b111100: data = 16'hffea;
      10'b111101: data = 16'hffe9;
      10'b111110: data = 16'hffe9;
      10'b111111: data = 16'hffe9;
      10'b1000000: data = 16'hffe8;
      10'b1000001: data = 16'hffe8;
      10'b1000010: data = 16'hffe8;
      10'b1000011: data = 16'hffe7;
      10'b1000100: data = 16'hffe7;
      10'b1000101: data = 16'hffe6;
      10'b1000110: data = 16'hffe6;
      10'b1000111: data = 16'hffe6;
      10'b1001000: data = 16'hffe5;
      10'b1001001: data = 16'hffe5;
      10'b1001010: data = 16'hffe5;
      10'b1001011: data = 16'hffe4;
      10'b1001100: data = 16'hffe4;
      10'b1001101: data = 16'hffe4;
      10'b1001110: data = 16'hffe3;
      10'b1001111: data = 16'hffe3;
      10'b1010000: data = 16'hffe2;
      10'b1010001: data = 16'hffe2;
      10'b1010010: data = 16'hffe2;
      10'b1010011: data = 16'hffe1;
      10'b1010100: data = 16'hffe1;
      10'b1010101: data = 16'hffe1;
      10'b1010110: data = 16'hffe0;
      10'b1010111: data = 16'hffe0;
      10'b1011000: data = 16'hffe0;
      10'b1011001: data = 16'hffdf;
      10'b1011010: data = 16'hffdf;
      10'b1011011: data = 16'hffde;
      10'b1011100: data = 16'hffde;
      10'b1011101: data = 16'hffde;
      10'b1011110: data = 16'hffdd;
      10'b1011111: data = 16'hffdd;
      10'b1100000: data = 16'hffdd;
      10'b1100001: data = 16'hffdc;
      10'b1100010: data = 16'hffdc;
      10'b1100011: data = 16'hffdc;
      10'b1100100: data = 16'hffdb;
      10'b1100101: data = 16'hffdb;
      10'b1100110: data = 16'hffda;
      10'b1100111: data = 16'hffda;
      10'b1101000: data = 16'hffda;
      10'b1101001: data = 16'hffd9;
      10'b1101010: data = 16'hffd9;
      10'b1101011: data = 16'hffd9;
      10'b1101100: data = 16'hffd8;
      10'b1101101: data = 16'hffd8;
      10'b1101110: data = 16'hffd8;
      10'b1101111: data = 16'hffd7;
      10'b1110000: data = 16'hffd7;
      10'b1110001: data = 16'hffd6;
      10'b1110010: data = 16'hffd6;
      10'b1110011: data = 16'hffd6;
      10'b1110100: data = 16'hffd5;
      10'b1110101: data = 16'hffd5;
      10'b1110110: data = 16'hffd5;
      10'b1110111: data = 16'hffd4;
      10'b1111000: data = 16'hffd4;
      10'b1111001: data = 16'hffd4;
      10'b1111010: data = 16'hffd3;
      10'b1111011: data = 16'hffd3;
      10'b1111100: data = 16'hffd2;
      10'b1111101: data = 16'hffd2;
      10'b1111110: data = 16'hffd2;
      10'b1111111: data = 16'hffd1;
      10'b10000000: data = 16'hffd1;
      10'b10000001: data = 16'hffd1;
      10'b10000010: data = 16'hffd0;
      10'b10000011: data = 16'hffd0;
      10'b10000100: data = 16'hffd0;
      10'b10000101: data = 16'hffcf;
      10'b10000110: data = 16'hffcf;
      10'b10000111: data = 16'hffce;
      10'b10001000: data = 16'hffce;
      10'b10001001: data = 16'hffce;
      10'b10001010: data = 16'hffcd;
      10'b10001011: data = 16'hffcd;
      10'b10001100: data = 16'hffcd;
      10'b10001101: data = 16'hffcc;
      10'b10001110: data = 16'hffcc;
      10'b10001111: data = 16'hffcc;
      10'b10010000: data = 16'hffcb;
      10'b10010001: data = 16'hffcb;
      10'b10010010: data = 16'hffca;
      10'b10010011: data = 16'hffca;
      10'b10010100: data = 16'hffca;
      10'b10010101: data = 16'hffc9;
      10'b10010110: data = 16'hffc9;
      10'b10010111: data = 16'hffc9;
      10'b10011000: data = 16'hffc8;
      10'b10011001: data = 16'hffc8;
      10'b10011010: data = 16'hffc8;
      10'b10011011: data = 16'hffc7;
      10'b10011100: data = 16'hffc7;
      10'b10011101: data = 16'hffc6;
      10'b10011110: data = 16'hffc6;
      10'b10011111: data = 16'hffc6;
      10'b10100000: data = 16'hffc5;
      10'b10100001: data = 16'hffc5;
      10'b10100010: data = 16'hffc5;
      10'b10100011: data = 16'hffc4;
      10'b10100100: data = 16'hffc4;
      10'b10100101: data = 16'hffc4;
      10'b10100110: data = 16'hffc3;
      10'b10100111: data = 16'hffc3;
      10'b10101000: data = 16'hffc2;
      10'b10101001: data = 16'hffc2;
      10'b10101010: data = 16'hffc2;
      10'b10101011: data = 16'hffc1;
      10'b10101100: data = 16'hffc1;
      10'b10101101: data = 16'hffc1;
      10'b10101110: data = 16'hffc0;
      10'b10101111: data = 16'hffc0;
      10'b10110000: data = 16'hffc0;
      10'b10110001: data = 16'hffbf;
      10'b10110010: data = 16'hffbf;
      10'b10110011: data = 16'hffbe;
      10'b10110100: data = 16'hffbe;
      10'b10110101: data = 16'hffbe;
      10'b10110110: data = 16'hffbd;
      10'b10110111: data = 16'hffbd;
      10'b10111000: data = 16'hffbd;
      10'b10111001: data = 16'hffbc;
      10'b10111010: data = 16'hffbc;
      10'b10111011: data = 16'hffbc;
      10'b10111100: data = 16'hffbb;
      10'b10111101: data = 16'hffbb;
      10'b10111110: data = 16'hffba;
      10'b10111111: data = 16'hffba;
      10'b11000000: data = 16'hffba;
      10'b11000001: data = 16'hffb9;
      10'b11000010: data = 16'hffb9;
      10'b11000011: data = 16'hffb9;
      10'b11000100: data = 16'hffb8;
      10'b11000101: data = 16'hffb8;
      10'b11000110: data = 16'hffb8;
      10'b11000111: data = 16'hffb7;
      10'b11001000: data = 16'hffb7;
      10'b11001001: data = 16'hffb6;
      10'b11001010: data = 16'hffb6;
      10'b11001011: data = 16'hffb6;
      10'b11001100: data = 16'hffb5;
      10'b11001101: data = 16'hffb5;
      10'b11001110: data = 16'hffb5;
      10'b11001111: data = 16'hffb4;
      10'b11010000: data = 16'hffb4;
      10'b11010001: data = 16'hffb4;
      10'b11010010: data = 16'hffb3;
      10'b11010011: data = 16'hffb3;
      10'b11010100: data = 16'hffb2;
      10'b11010101: data = 16'hffb2;
      10'b11010110: data = 16'hffb2;
      10'b11010111: data = 16'hffb1;
      10'b11011000: data = 16'hffb1;
      10'b11011001: data = 16'hffb1;
      10'b11011010: data = 16'hffb0;
      10'b11011011: data = 16'hffb0;
      10'b11011100: data = 16'hffb0;
      10'b11011101: data = 16'hffaf;
      10'b11011110: data = 16'hffaf;
      10'b11011111: data = 16'hffae;
      10'b11100000: data = 16'hffae;
      10'b11100001: data = 16'hffae;
      10'b11100010: data = 16'hffad;
      10'b11100011: data = 16'hffad;
      10'b11100100: data = 16'hffad;
      10'b11100101: data = 16'hffac;
      10'b11100110: data = 16'hffac;
      10'b11100111: data = 16'hffac;
      10'b11101000: data = 16'hffab;
      10'b11101001: data = 16'hffab;
      10'b11101010: data = 16'hffaa;
      10'b11101011: data = 16'hffaa;
      10'b11101100: data = 16'hffaa;
      10'b11101101: data = 16'hffa9;
      10'b11101110: data = 16'hffa9;
      10'b11101111: data = 16'hffa9;
      10'b11110000: data = 16'hffa8;
      10'b11110001: data = 16'hffa8;
      10'b11110010: data = 16'hffa8;
      10'b11110011: data = 16'hffa7;
      10'b11110100: data = 16'hffa7;
      10'b11110101: data = 16'hffa6;
      10'b11110110: data = 16'hffa6;
      10'b11110111: data = 16'hffa6;
      10'b11111000: data = 16'hffa5;
      10'b11111001: data = 16'hffa5;
      10'b11111010: data = 16'hffa5;
      10'b11111011: data = 16'hffa4;
      10'b11111100: data = 16'hffa4;
      10'b11111101: data = 16'hffa4;
      10'b11111110: data = 16'hffa3;
      10'b11111111: data = 16'hffa3;
      10'b100000000: data = 16'hffa3;
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
    reg [15:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
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
    reg [15:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
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
      'h2: data = 16'h1;
      'h3: data = 16'h1;
      'h4: data = 16'h2;
      'h5: data = 16'h3;
      'h6: data = 16'h3;
      'h7: data = 16'h4;
      'h8: data = 16'h4;
      'h9: data = 16'h5;
      'ha: data = 16'h6;
      'hb: data = 16'h6;
      'hc: data = 16'h7;
      'hd: data = 16'h7;
      'he: data = 16'h8;
      'hf: data = 16'h9;
      'h10: data = 16'h9;
      'h11: data = 16'ha;
      'h12: data = 16'hb;
      'h13: data = 16'hb;
      'h14: data = 16'hc;
      'h15: data = 16'hc;
      'h16: data = 16'hd;
      'h17: data = 16'he;
      'h18: data = 16'he;
      'h19: data = 16'hf;
      'h1a: data = 16'hf;
      'h1b: data = 16'h10;
      'h1c: data = 16'h11;
      'h1d: data = 16'h11;
      'h1e: data = 16'h12;
      'h1f: data = 16'h13;
      'h20: data = 16'h13;
      'h21: data = 16'h14;
      'h22: data = 16'h14;
      'h23: data = 16'h15;
      'h24: data = 16'h16;
      'h25: data = 16'h16;
      'h26: data = 16'h17;
      'h27: data = 16'h17;
      'h28: data = 16'h18;
      'h29: data = 16'h19;
      'h2a: data = 16'h19;
      'h2b: data = 16'h1a;
      'h2c: data = 16'h1a;
      'h2d: data = 16'h1b;
      'h2e: data = 16'h1c;
      'h2f: data = 16'h1c;
      'h30: data = 16'h1d;
      'h31: data = 16'h1e;
      'h32: data = 16'h1e;
      'h33: data = 16'h1f;
      'h34: data = 16'h1f;
      'h35: data = 16'h20;
      'h36: data = 16'h21;
      'h37: data = 16'h21;
      'h38: data = 16'h22;
      'h39: data = 16'h22;
      'h3a: data = 16'h23;
      'h3b: data = 16'h24;
      'h3c: data = 16'h24;
      'h3d: data = 16'h25;
      'h3e: data = 16'h26;
      'h3f: data = 16'h26;
      'h40: data = 16'h27;
      'h41: data = 16'h27;
      'h42: data = 16'h28;
      'h43: data = 16'h29;
      'h44: data = 16'h29;
      'h45: data = 16'h2a;
      'h46: data = 16'h2a;
      'h47: data = 16'h2b;
      'h48: data = 16'h2c;
      'h49: data = 16'h2c;
      'h4a: data = 16'h2d;
      'h4b: data = 16'h2d;
      'h4c: data = 16'h2e;
      'h4d: data = 16'h2f;
      'h4e: data = 16'h2f;
      'h4f: data = 16'h30;
      'h50: data = 16'h31;
      'h51: data = 16'h31;
      'h52: data = 16'h32;
      'h53: data = 16'h32;
      'h54: data = 16'h33;
      'h55: data = 16'h34;
      'h56: data = 16'h34;
      'h57: data = 16'h35;
      'h58: data = 16'h35;
      'h59: data = 16'h36;
      'h5a: data = 16'h37;
      'h5b: data = 16'h37;
      'h5c: data = 16'h38;
      'h5d: data = 16'h39;
      'h5e: data = 16'h39;
      'h5f: data = 16'h3a;
      'h60: data = 16'h3a;
      'h61: data = 16'h3b;
      'h62: data = 16'h3c;
      'h63: data = 16'h3c;
      'h64: data = 16'h3d;
      'h65: data = 16'h3d;
      'h66: data = 16'h3e;
      'h67: data = 16'h3f;
      'h68: data = 16'h3f;
      'h69: data = 16'h40;
      'h6a: data = 16'h41;
      'h6b: data = 16'h41;
      'h6c: data = 16'h42;
      'h6d: data = 16'h42;
      'h6e: data = 16'h43;
      'h6f: data = 16'h44;
      'h70: data = 16'h44;
      'h71: data = 16'h45;
      'h72: data = 16'h45;
      'h73: data = 16'h46;
      'h74: data = 16'h47;
      'h75: data = 16'h47;
      'h76: data = 16'h48;
      'h77: data = 16'h48;
      'h78: data = 16'h49;
      'h79: data = 16'h4a;
      'h7a: data = 16'h4a;
      'h7b: data = 16'h4b;
      'h7c: data = 16'h4c;
      'h7d: data = 16'h4c;
      'h7e: data = 16'h4d;
      'h7f: data = 16'h4d;
      'h80: data = 16'h4e;
      'h81: data = 16'h4f;
      'h82: data = 16'h4f;
      'h83: data = 16'h50;
      'h84: data = 16'h50;
      'h85: data = 16'h51;
      'h86: data = 16'h52;
      'h87: data = 16'h52;
      'h88: data = 16'h53;
      'h89: data = 16'h54;
      'h8a: data = 16'h54;
      'h8b: data = 16'h55;
      'h8c: data = 16'h55;
      'h8d: data = 16'h56;
      'h8e: data = 16'h57;
      'h8f: data = 16'h57;
      'h90: data = 16'h58;
      'h91: data = 16'h58;
      'h92: data = 16'h59;
      'h93: data = 16'h5a;
      'h94: data = 16'h5a;
      'h95: data = 16'h5b;
      'h96: data = 16'h5b;
      'h97: data = 16'h5c;
      'h98: data = 16'h5d;
      'h99: data = 16'h5d;
      'h9a: data = 16'h5e;
      'h9b: data = 16'h5f;
      'h9c: data = 16'h5f;
      'h9d: data = 16'h60;
      'h9e: data = 16'h60;
      'h9f: data = 16'h61;
      'ha0: data = 16'h62;
      'ha1: data = 16'h62;
      'ha2: data = 16'h63;
      'ha3: data = 16'h63;
      'ha4: data = 16'h64;
      'ha5: data = 16'h65;
      'ha6: data = 16'h65;
      'ha7: data = 16'h66;
      'ha8: data = 16'h67;
      'ha9: data = 16'h67;
      'haa: data = 16'h68;
      'hab: data = 16'h68;
      'hac: data = 16'h69;
      'had: data = 16'h6a;
      'hae: data = 16'h6a;
      'haf: data = 16'h6b;
      'hb0: data = 16'h6b;
      'hb1: data = 16'h6c;
      'hb2: data = 16'h6d;
      'hb3: data = 16'h6d;
      'hb4: data = 16'h6e;
      'hb5: data = 16'h6f;
      'hb6: data = 16'h6f;
      'hb7: data = 16'h70;
      'hb8: data = 16'h70;
      'hb9: data = 16'h71;
      'hba: data = 16'h72;
      'hbb: data = 16'h72;
      'hbc: data = 16'h73;
      'hbd: data = 16'h73;
      'hbe: data = 16'h74;
      'hbf: data = 16'h75;
      'hc0: data = 16'h75;
      'hc1: data = 16'h76;
      'hc2: data = 16'h76;
      'hc3: data = 16'h77;
      'hc4: data = 16'h78;
      'hc5: data = 16'h78;
      'hc6: data = 16'h79;
      'hc7: data = 16'h7a;
      'hc8: data = 16'h7a;
      'hc9: data = 16'h7b;
      'hca: data = 16'h7b;
      'hcb: data = 16'h7c;
      'hcc: data = 16'h7d;
      'hcd: data = 16'h7d;
      'hce: data = 16'h7e;
      'hcf: data = 16'h7e;
      'hd0: data = 16'h7f;
      'hd1: data = 16'h80;
      'hd2: data = 16'h80;
      'hd3: data = 16'h81;
      'hd4: data = 16'h82;
      'hd5: data = 16'h82;
      'hd6: data = 16'h83;
      'hd7: data = 16'h83;
      'hd8: data = 16'h84;
      'hd9: data = 16'h85;
      'hda: data = 16'h85;
      'hdb: data = 16'h86;
      'hdc: data = 16'h86;
      'hdd: data = 16'h87;
      'hde: data = 16'h88;
      'hdf: data = 16'h88;
      'he0: data = 16'h89;
      'he1: data = 16'h89;
      'he2: data = 16'h8a;
      'he3: data = 16'h8b;
      'he4: data = 16'h8b;
      'he5: data = 16'h8c;
      'he6: data = 16'h8d;
      'he7: data = 16'h8d;
      'he8: data = 16'h8e;
      'he9: data = 16'h8e;
      'hea: data = 16'h8f;
      'heb: data = 16'h90;
      'hec: data = 16'h90;
      'hed: data = 16'h91;
      'hee: data = 16'h91;
      'hef: data = 16'h92;
      'hf0: data = 16'h93;
      'hf1: data = 16'h93;
      'hf2: data = 16'h94;
      'hf3: data = 16'h95;
      'hf4: data = 16'h95;
      'hf5: data = 16'h96;
      'hf6: data = 16'h96;
      'hf7: data = 16'h97;
      'hf8: data = 16'h98;
      'hf9: data = 16'h98;
      'hfa: data = 16'h99;
      'hfb: data = 16'h99;
      'hfc: data = 16'h9a;
      'hfd: data = 16'h9b;
      'hfe: data = 16'h9b;
      'hff: data = 16'h9c;
      'h100: data = 16'h9d;
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
    localparam  last_tick = 16'h6800;
    localparam  last_period = 16'h19f;
    localparam  last_write_period = 16'h19e;
    localparam  last_plane = 16'hff;
    localparam  last_chunk = 16'h67;
    localparam  last_ray = 16'hce;
    localparam  last_segment = 16'h7f;
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
