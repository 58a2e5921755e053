module top$pipeline$control(clock,host_write,host_address,host_data,start,valid,first,unit_valid,unit_first,unit_last,unit_cast,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3,in_volume,in_inner,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  start;
    input wire  valid;
    output reg  first;
    output reg  unit_valid;
    output reg  unit_first;
    output reg  unit_last;
    output reg  unit_cast;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wx$2;
    output reg  [15:0] wx$3;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [15:0] wy$2;
    output reg  [15:0] wy$3;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  per_ray = 1'b0;
    localparam  lane_bit$0 = 8'h1;
    localparam  lane_bit$1 = 8'h2;
    localparam  lane_bit$2 = 8'h4;
    localparam  lane_bit$3 = 8'h8;
    localparam  lane_bit$4 = 8'h10;
    localparam  lane_bit$5 = 8'h20;
    localparam  lane_bit$6 = 8'h40;
    localparam  lane_bit$7 = 8'h80;
    localparam  valid_flag = 64'h1000000000000;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    wire  [63:0] regs$q$2;
    wire  [63:0] regs$q$3;
    reg  [15:0] segment$d;
    wire  [15:0] segment$q;
    reg  segment$clock;
    reg  [15:0] ray$d;
    wire  [15:0] ray$q;
    reg  ray$clock;
    reg  [15:0] scanline$d;
    wire  [15:0] scanline$q;
    reg  scanline$clock;
    reg  late$clock;
    reg  [63:0] late$data_in;
    reg  late$write_enable;
    wire  [63:0] late$data_out;
    reg  [15:0] late$last;
    reg  templates$clock;
    reg  templates$host_write;
    reg  [23:0] templates$host_address;
    reg  [63:0] templates$host_data;
    reg  [15:0] templates$stride;
    reg  [15:0] templates$ray;
    reg  [15:0] templates$scanline;
    reg  [15:0] templates$segment;
    wire  [15:0] templates$wx$0;
    wire  [15:0] templates$wx$1;
    wire  [15:0] templates$wx$2;
    wire  [15:0] templates$wx$3;
    wire  [15:0] templates$wy$0;
    wire  [15:0] templates$wy$1;
    wire  [15:0] templates$wy$2;
    wire  [15:0] templates$wy$3;
    reg  increments$clock;
    reg  increments$host_write;
    reg  [23:0] increments$host_address;
    reg  [63:0] increments$host_data;
    reg  [15:0] increments$centre_last;
    reg  [15:0] increments$ray;
    reg  [15:0] increments$scanline;
    wire  increments$dx_neg;
    wire  [15:0] increments$dx_mag;
    wire  increments$dy_neg;
    wire  [15:0] increments$dy_mag;
    reg  bounds$0$clock;
    reg  bounds$0$host_write;
    reg  [23:0] bounds$0$host_address;
    reg  [63:0] bounds$0$host_data;
    reg  [7:0] bounds$0$address;
    wire  [63:0] bounds$0$data;
    reg  bounds$1$clock;
    reg  bounds$1$host_write;
    reg  [23:0] bounds$1$host_address;
    reg  [63:0] bounds$1$host_data;
    reg  [7:0] bounds$1$address;
    wire  [63:0] bounds$1$data;
    reg  bounds$2$clock;
    reg  bounds$2$host_write;
    reg  [23:0] bounds$2$host_address;
    reg  [63:0] bounds$2$host_data;
    reg  [7:0] bounds$2$address;
    wire  [63:0] bounds$2$data;
    reg  bounds$3$clock;
    reg  bounds$3$host_write;
    reg  [23:0] bounds$3$host_address;
    reg  [63:0] bounds$3$host_data;
    reg  [7:0] bounds$3$address;
    wire  [63:0] bounds$3$data;
    reg  inner$0$clock;
    reg  inner$0$host_write;
    reg  [23:0] inner$0$host_address;
    reg  [63:0] inner$0$host_data;
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  inner$1$clock;
    reg  inner$1$host_write;
    reg  [23:0] inner$1$host_address;
    reg  [63:0] inner$1$host_data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    reg  inner$2$clock;
    reg  inner$2$host_write;
    reg  [23:0] inner$2$host_address;
    reg  [63:0] inner$2$host_data;
    reg  [7:0] inner$2$address;
    wire  [63:0] inner$2$data;
    reg  inner$3$clock;
    reg  inner$3$host_write;
    reg  [23:0] inner$3$host_address;
    reg  [63:0] inner$3$host_data;
    reg  [7:0] inner$3$address;
    wire  [63:0] inner$3$data;
    
    // Local signals
    reg  [15:0] last_segment;
    reg  [15:0] last_ray;
    reg  [15:0] unit_segment;
    reg  [15:0] unit_ray;
    reg  [15:0] unit_scanline;
    reg  [15:0] cast_ray_lo;
    reg  [15:0] cast_ray_span;
    reg  [15:0] cast_line_lo;
    reg  [15:0] cast_line_span;
    reg  [7:0] lane_in$0;
    reg  [7:0] lane_in$1;
    reg  [7:0] lane_in$2;
    reg  [7:0] lane_in$3;
    reg  [7:0] lane_in$4;
    reg  [7:0] lane_in$5;
    reg  [7:0] lane_in$6;
    reg  [7:0] lane_in$7;
    reg  [7:0] lane_inner$0;
    reg  [7:0] lane_inner$1;
    reg  [7:0] lane_inner$2;
    reg  [7:0] lane_inner$3;
    reg  [7:0] lane_inner$4;
    reg  [7:0] lane_inner$5;
    reg  [7:0] lane_inner$6;
    reg  [7:0] lane_inner$7;
    
    // Sub module instances
    top$pipeline$control$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1),
        .q$2(regs$q$2),
        .q$3(regs$q$3)
    );
    top$pipeline$control$segment segment(
        .d(segment$d),
        .q(segment$q),
        .clock(segment$clock)
    );
    top$pipeline$control$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    top$pipeline$control$scanline scanline(
        .d(scanline$d),
        .q(scanline$q),
        .clock(scanline$clock)
    );
    top$pipeline$control$late late(
        .clock(late$clock),
        .data_in(late$data_in),
        .write_enable(late$write_enable),
        .data_out(late$data_out),
        .last(late$last)
    );
    top$pipeline$control$templates templates(
        .clock(templates$clock),
        .host_write(templates$host_write),
        .host_address(templates$host_address),
        .host_data(templates$host_data),
        .stride(templates$stride),
        .ray(templates$ray),
        .scanline(templates$scanline),
        .segment(templates$segment),
        .wx$0(templates$wx$0),
        .wx$1(templates$wx$1),
        .wx$2(templates$wx$2),
        .wx$3(templates$wx$3),
        .wy$0(templates$wy$0),
        .wy$1(templates$wy$1),
        .wy$2(templates$wy$2),
        .wy$3(templates$wy$3)
    );
    top$pipeline$control$increments increments(
        .clock(increments$clock),
        .host_write(increments$host_write),
        .host_address(increments$host_address),
        .host_data(increments$host_data),
        .centre_last(increments$centre_last),
        .ray(increments$ray),
        .scanline(increments$scanline),
        .dx_neg(increments$dx_neg),
        .dx_mag(increments$dx_mag),
        .dy_neg(increments$dy_neg),
        .dy_mag(increments$dy_mag)
    );
    top$pipeline$control$bounds$0 bounds$0(
        .clock(bounds$0$clock),
        .host_write(bounds$0$host_write),
        .host_address(bounds$0$host_address),
        .host_data(bounds$0$host_data),
        .address(bounds$0$address),
        .data(bounds$0$data)
    );
    top$pipeline$control$bounds$1 bounds$1(
        .clock(bounds$1$clock),
        .host_write(bounds$1$host_write),
        .host_address(bounds$1$host_address),
        .host_data(bounds$1$host_data),
        .address(bounds$1$address),
        .data(bounds$1$data)
    );
    top$pipeline$control$bounds$2 bounds$2(
        .clock(bounds$2$clock),
        .host_write(bounds$2$host_write),
        .host_address(bounds$2$host_address),
        .host_data(bounds$2$host_data),
        .address(bounds$2$address),
        .data(bounds$2$data)
    );
    top$pipeline$control$bounds$3 bounds$3(
        .clock(bounds$3$clock),
        .host_write(bounds$3$host_write),
        .host_address(bounds$3$host_address),
        .host_data(bounds$3$host_data),
        .address(bounds$3$address),
        .data(bounds$3$data)
    );
    top$pipeline$control$inner$0 inner$0(
        .clock(inner$0$clock),
        .host_write(inner$0$host_write),
        .host_address(inner$0$host_address),
        .host_data(inner$0$host_data),
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .clock(inner$1$clock),
        .host_write(inner$1$host_write),
        .host_address(inner$1$host_address),
        .host_data(inner$1$host_data),
        .address(inner$1$address),
        .data(inner$1$data)
    );
    top$pipeline$control$inner$2 inner$2(
        .clock(inner$2$clock),
        .host_write(inner$2$host_write),
        .host_address(inner$2$host_address),
        .host_data(inner$2$host_data),
        .address(inner$2$address),
        .data(inner$2$data)
    );
    top$pipeline$control$inner$3 inner$3(
        .clock(inner$3$clock),
        .host_write(inner$3$host_write),
        .host_address(inner$3$host_address),
        .host_data(inner$3$host_data),
        .address(inner$3$address),
        .data(inner$3$data)
    );
    
    // Update code
    always @(*) begin
        segment$clock = clock;
        ray$clock = clock;
        scanline$clock = clock;
        segment$d = segment$q;
        ray$d = ray$q;
        scanline$d = scanline$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        last_ray = regs$q$0[('h0)+:(16)] - 'h1;
        last_segment = regs$q$0[('h20)+:(16)] - 'h1;
        cast_ray_lo = regs$q$2[('h0)+:(16)];
        cast_ray_span = regs$q$2[('h10)+:(16)];
        cast_line_lo = regs$q$2[('h20)+:(16)];
        cast_line_span = regs$q$2[('h30)+:(16)];
        late$clock = clock;
        late$last = regs$q$3[('h0)+:(16)];
        late$write_enable = 1'b1;
        increments$clock = clock;
        increments$host_write = host_write;
        increments$host_address = host_address;
        increments$host_data = host_data;
        increments$centre_last = regs$q$3[('h20)+:(16)];
        templates$clock = clock;
        templates$host_write = host_write;
        templates$host_address = host_address;
        templates$host_data = host_data;
        templates$stride = regs$q$1[('h30)+:(16)];
        if (valid) begin
            segment$d = segment$q + 'h1;
            if (segment$q == last_segment) begin
                segment$d = 'h0;
                ray$d = ray$q + 'h1;
                if (ray$q == last_ray) begin
                    ray$d = 'h0;
                    scanline$d = scanline$q + 'h1;
                end
            end
        end
        if (start) begin
            segment$d = 'h0;
            ray$d = 'h0;
            scanline$d = 'h0;
        end
        first = valid & ~|segment$q;
        late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20);
        if (valid) begin
            late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20) | valid_flag;
        end
        unit_segment = late$data_out[('h0)+:(16)];
        unit_ray = late$data_out[('h10)+:(16)];
        unit_scanline = late$data_out[('h20)+:(16)];
        unit_valid = late$data_out['h30];
        unit_first = late$data_out['h30] & ~|unit_segment;
        unit_last = late$data_out['h30] & (unit_segment == last_segment);
        unit_cast = ~per_ray | (((unit_ray - cast_ray_lo) <= cast_ray_span) & ((unit_scanline - cast_line_lo) <= cast_line_span));
        increments$ray = unit_ray;
        increments$scanline = unit_scanline;
        dx_neg = increments$dx_neg;
        dx_mag = increments$dx_mag;
        dy_neg = increments$dy_neg;
        dy_mag = increments$dy_mag;
        templates$ray = unit_ray;
        templates$scanline = unit_scanline;
        templates$segment = unit_segment;
        lane_in$0 = 'h0;
        lane_inner$0 = 'h0;
        lane_in$1 = 'h0;
        lane_inner$1 = 'h0;
        lane_in$2 = 'h0;
        lane_inner$2 = 'h0;
        lane_in$3 = 'h0;
        lane_inner$3 = 'h0;
        lane_in$4 = 'h0;
        lane_inner$4 = 'h0;
        lane_in$5 = 'h0;
        lane_inner$5 = 'h0;
        lane_in$6 = 'h0;
        lane_inner$6 = 'h0;
        lane_in$7 = 'h0;
        lane_inner$7 = 'h0;
        bounds$0$clock = clock;
        bounds$0$host_write = host_write;
        bounds$0$host_address = host_address;
        bounds$0$host_data = host_data;
        inner$0$clock = clock;
        inner$0$host_write = host_write;
        inner$0$host_address = host_address;
        inner$0$host_data = host_data;
        bounds$0$address = unit_segment[('h0)+:(8)];
        wx$0 = templates$wx$0;
        wy$0 = templates$wy$0;
        if ((unit_ray >= bounds$0$data[('h0)+:(16)]) & (unit_ray <= bounds$0$data[('h10)+:(16)]) & (unit_scanline >= bounds$0$data[('h20)+:(16)]) & (unit_scanline <= bounds$0$data[('h30)+:(16)])) begin
            lane_in$0 = lane_bit$0;
        end
        inner$0$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$0$data[('h0)+:(16)]) & (unit_ray <= inner$0$data[('h10)+:(16)]) & (unit_scanline >= inner$0$data[('h20)+:(16)]) & (unit_scanline <= inner$0$data[('h30)+:(16)])) begin
            lane_inner$0 = lane_bit$0;
        end
        bounds$1$clock = clock;
        bounds$1$host_write = host_write;
        bounds$1$host_address = host_address;
        bounds$1$host_data = host_data;
        inner$1$clock = clock;
        inner$1$host_write = host_write;
        inner$1$host_address = host_address;
        inner$1$host_data = host_data;
        bounds$1$address = unit_segment[('h0)+:(8)];
        wx$1 = templates$wx$1;
        wy$1 = templates$wy$1;
        if ((unit_ray >= bounds$1$data[('h0)+:(16)]) & (unit_ray <= bounds$1$data[('h10)+:(16)]) & (unit_scanline >= bounds$1$data[('h20)+:(16)]) & (unit_scanline <= bounds$1$data[('h30)+:(16)])) begin
            lane_in$1 = lane_bit$1;
        end
        inner$1$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$1$data[('h0)+:(16)]) & (unit_ray <= inner$1$data[('h10)+:(16)]) & (unit_scanline >= inner$1$data[('h20)+:(16)]) & (unit_scanline <= inner$1$data[('h30)+:(16)])) begin
            lane_inner$1 = lane_bit$1;
        end
        bounds$2$clock = clock;
        bounds$2$host_write = host_write;
        bounds$2$host_address = host_address;
        bounds$2$host_data = host_data;
        inner$2$clock = clock;
        inner$2$host_write = host_write;
        inner$2$host_address = host_address;
        inner$2$host_data = host_data;
        bounds$2$address = unit_segment[('h0)+:(8)];
        wx$2 = templates$wx$2;
        wy$2 = templates$wy$2;
        if ((unit_ray >= bounds$2$data[('h0)+:(16)]) & (unit_ray <= bounds$2$data[('h10)+:(16)]) & (unit_scanline >= bounds$2$data[('h20)+:(16)]) & (unit_scanline <= bounds$2$data[('h30)+:(16)])) begin
            lane_in$2 = lane_bit$2;
        end
        inner$2$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$2$data[('h0)+:(16)]) & (unit_ray <= inner$2$data[('h10)+:(16)]) & (unit_scanline >= inner$2$data[('h20)+:(16)]) & (unit_scanline <= inner$2$data[('h30)+:(16)])) begin
            lane_inner$2 = lane_bit$2;
        end
        bounds$3$clock = clock;
        bounds$3$host_write = host_write;
        bounds$3$host_address = host_address;
        bounds$3$host_data = host_data;
        inner$3$clock = clock;
        inner$3$host_write = host_write;
        inner$3$host_address = host_address;
        inner$3$host_data = host_data;
        bounds$3$address = unit_segment[('h0)+:(8)];
        wx$3 = templates$wx$3;
        wy$3 = templates$wy$3;
        if ((unit_ray >= bounds$3$data[('h0)+:(16)]) & (unit_ray <= bounds$3$data[('h10)+:(16)]) & (unit_scanline >= bounds$3$data[('h20)+:(16)]) & (unit_scanline <= bounds$3$data[('h30)+:(16)])) begin
            lane_in$3 = lane_bit$3;
        end
        inner$3$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$3$data[('h0)+:(16)]) & (unit_ray <= inner$3$data[('h10)+:(16)]) & (unit_scanline >= inner$3$data[('h20)+:(16)]) & (unit_scanline <= inner$3$data[('h30)+:(16)])) begin
            lane_inner$3 = lane_bit$3;
        end
        in_volume = lane_in$0 | lane_in$1 | lane_in$2 | lane_in$3 | lane_in$4 | lane_in$5 | lane_in$6 | lane_in$7;
        in_inner = lane_inner$0 | lane_inner$1 | lane_inner$2 | lane_inner$3 | lane_inner$4 | lane_inner$5 | lane_inner$6 | lane_inner$7;
    end
    
endmodule // top$pipeline$control
module top$pipeline$control$bounds$0(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd655360 && host_address < 24'd655368) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$bounds$0
module top$pipeline$control$bounds$1(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd655616 && host_address < 24'd655624) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$bounds$1
module top$pipeline$control$bounds$2(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd655872 && host_address < 24'd655880) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$bounds$2
module top$pipeline$control$bounds$3(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd656128 && host_address < 24'd656136) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$bounds$3
module top$pipeline$control$increments(clock,host_write,host_address,host_data,centre_last,ray,scanline,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] centre_last;
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  mask = 16'h0;
    
    // Stub signals
    reg  centre_line$clock;
    reg  [31:0] centre_line$data_in;
    reg  centre_line$write_enable;
    wire  [31:0] centre_line$data_out;
    reg  [15:0] centre_line$last;
    reg  dx_rom$clock;
    reg  dx_rom$host_write;
    reg  [23:0] dx_rom$host_address;
    reg  [63:0] dx_rom$host_data;
    reg  [15:0] dx_rom$address;
    wire  [16:0] dx_rom$data;
    reg  dy_rom$clock;
    reg  dy_rom$host_write;
    reg  [23:0] dy_rom$host_address;
    reg  [63:0] dy_rom$host_data;
    reg  [15:0] dy_rom$address;
    wire  [16:0] dy_rom$data;
    reg  [16:0] dx_q$d;
    wire  [16:0] dx_q$q;
    reg  dx_q$clock;
    reg  [16:0] dy_q$d;
    wire  [16:0] dy_q$q;
    reg  dy_q$clock;
    
    // Local signals
    reg  [15:0] dx_address;
    reg  [15:0] dy_address;
    
    // Sub module instances
    top$pipeline$control$increments$centre_line centre_line(
        .clock(centre_line$clock),
        .data_in(centre_line$data_in),
        .write_enable(centre_line$write_enable),
        .data_out(centre_line$data_out),
        .last(centre_line$last)
    );
    top$pipeline$control$increments$dx_rom dx_rom(
        .clock(dx_rom$clock),
        .host_write(dx_rom$host_write),
        .host_address(dx_rom$host_address),
        .host_data(dx_rom$host_data),
        .address(dx_rom$address),
        .data(dx_rom$data)
    );
    top$pipeline$control$increments$dy_rom dy_rom(
        .clock(dy_rom$clock),
        .host_write(dy_rom$host_write),
        .host_address(dy_rom$host_address),
        .host_data(dy_rom$host_data),
        .address(dy_rom$address),
        .data(dy_rom$data)
    );
    top$pipeline$control$increments$dx_q dx_q(
        .d(dx_q$d),
        .q(dx_q$q),
        .clock(dx_q$clock)
    );
    top$pipeline$control$increments$dy_q dy_q(
        .d(dy_q$d),
        .q(dy_q$q),
        .clock(dy_q$clock)
    );
    
    // Update code
    always @(*) begin
        dx_q$clock = clock;
        dy_q$clock = clock;
        dx_q$d = dx_q$q;
        dy_q$d = dy_q$q;
        centre_line$clock = clock;
        centre_line$last = centre_last;
        dx_rom$clock = clock;
        dx_rom$host_write = host_write;
        dx_rom$host_address = host_address;
        dx_rom$host_data = host_data;
        dy_rom$clock = clock;
        dy_rom$host_write = host_write;
        dy_rom$host_address = host_address;
        dy_rom$host_data = host_data;
        centre_line$write_enable = 1'b1;
        centre_line$data_in = 32'(ray) | (32'(scanline) << 'h10);
        dx_address = centre_line$data_out[('h0)+:(16)] & mask;
        dy_address = (centre_line$data_out[('h10)+:(16)] - 'h1) & mask;
        dx_rom$address = dx_address;
        dy_rom$address = dy_address;
        dx_q$d = dx_rom$data;
        dy_q$d = dy_rom$data;
        dx_neg = dx_q$q['h10];
        dx_mag = dx_q$q[('h0)+:(16)];
        dy_neg = dy_q$q['h10];
        dy_mag = dy_q$q[('h0)+:(16)];
    end
    
endmodule // top$pipeline$control$increments
module top$pipeline$control$increments$centre_line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h1;
    localparam  single = 1'b1;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$increments$centre_line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$increments$centre_line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$increments$centre_line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$control$increments$centre_line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$control$increments$centre_line
module top$pipeline$control$increments$centre_line$one(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$one
module top$pipeline$control$increments$centre_line$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$ptr
module top$pipeline$control$increments$centre_line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$increments$centre_line$ram
module top$pipeline$control$increments$centre_line$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$rd_flipped
module top$pipeline$control$increments$dx_q(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$increments$dx_q
module top$pipeline$control$increments$dx_rom(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    reg [16:0] mem[1:0];
    integer i;
    initial begin
       for (i = 0; i <= 1; i = i + 1) mem[i] = 17'd0;
    end
    
    always @(*) data = mem[address[0:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd327680 && host_address < 24'd327682) begin
          mem[host_address[0:0]] <= host_data[16:0];
       end
    end
endmodule // top$pipeline$control$increments$dx_rom
module top$pipeline$control$increments$dy_q(d,q,clock);
    
    // Module arguments
    input wire  [16:0] d;
    output reg  [16:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 17'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$increments$dy_q
module top$pipeline$control$increments$dy_rom(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    reg [16:0] mem[1:0];
    integer i;
    initial begin
       for (i = 0; i <= 1; i = i + 1) mem[i] = 17'd0;
    end
    
    always @(*) data = mem[address[0:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd393216 && host_address < 24'd393218) begin
          mem[host_address[0:0]] <= host_data[16:0];
       end
    end
endmodule // top$pipeline$control$increments$dy_rom
module top$pipeline$control$inner$0(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd659456 && host_address < 24'd659464) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$inner$0
module top$pipeline$control$inner$1(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd659712 && host_address < 24'd659720) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$inner$2(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd659968 && host_address < 24'd659976) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$inner$2
module top$pipeline$control$inner$3(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    reg [63:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 64'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd660224 && host_address < 24'd660232) begin
          mem[host_address[2:0]] <= host_data[63:0];
       end
    end
endmodule // top$pipeline$control$inner$3
module top$pipeline$control$late(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 64'hffffffffffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [63:0] line$data_in;
    reg  line$write_enable;
    wire  [63:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [63:0] out$d;
    wire  [63:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$control$late$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$control$late$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$control$late$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$control$late
module top$pipeline$control$late$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h7;
    localparam  single = 1'b0;
    localparam  mask = 64'hffffffffffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$late$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$late$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$late$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$control$late$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$control$late$line
module top$pipeline$control$late$line$one(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$line$one
module top$pipeline$control$late$line$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$line$ptr
module top$pipeline$control$late$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [63:0] mem[7:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$late$line$ram
module top$pipeline$control$late$line$rd_flipped(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$line$rd_flipped
module top$pipeline$control$late$line_last(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$line_last
module top$pipeline$control$late$out(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$out
module top$pipeline$control$ray(d,q,clock);
    
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
          
endmodule // top$pipeline$control$ray
module top$pipeline$control$regs(clock,host_write,host_address,host_data,q$0,q$1,q$2,q$3);
    
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
    localparam  address$1 = 24'h32;
    localparam  address$2 = 24'h35;
    localparam  address$3 = 24'h36;
    
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
    top$pipeline$control$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$control$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    top$pipeline$control$regs$r$2 r$2(
        .d(r$2$d),
        .q(r$2$q),
        .clock(r$2$clock)
    );
    top$pipeline$control$regs$r$3 r$3(
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
    
endmodule // top$pipeline$control$regs
module top$pipeline$control$regs$r$0(d,q,clock);
    
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
          
endmodule // top$pipeline$control$regs$r$0
module top$pipeline$control$regs$r$1(d,q,clock);
    
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
          
endmodule // top$pipeline$control$regs$r$1
module top$pipeline$control$regs$r$2(d,q,clock);
    
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
          
endmodule // top$pipeline$control$regs$r$2
module top$pipeline$control$regs$r$3(d,q,clock);
    
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
          
endmodule // top$pipeline$control$regs$r$3
module top$pipeline$control$scanline(d,q,clock);
    
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
          
endmodule // top$pipeline$control$scanline
module top$pipeline$control$segment(d,q,clock);
    
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
          
endmodule // top$pipeline$control$segment
module top$pipeline$control$templates(clock,host_write,host_address,host_data,stride,ray,scanline,segment,wx$0,wx$1,wx$2,wx$3,wy$0,wy$1,wy$2,wy$3);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] stride;
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    input wire  [15:0] segment;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wx$2;
    output reg  [15:0] wx$3;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [15:0] wy$2;
    output reg  [15:0] wy$3;
    
    // Constant declarations
    localparam  per_ray = 1'b0;
    
    // Stub signals
    reg  wx_rom$0$clock;
    reg  wx_rom$0$host_write;
    reg  [23:0] wx_rom$0$host_address;
    reg  [63:0] wx_rom$0$host_data;
    reg  [15:0] wx_rom$0$address;
    wire  [15:0] wx_rom$0$data;
    reg  wx_rom$1$clock;
    reg  wx_rom$1$host_write;
    reg  [23:0] wx_rom$1$host_address;
    reg  [63:0] wx_rom$1$host_data;
    reg  [15:0] wx_rom$1$address;
    wire  [15:0] wx_rom$1$data;
    reg  wx_rom$2$clock;
    reg  wx_rom$2$host_write;
    reg  [23:0] wx_rom$2$host_address;
    reg  [63:0] wx_rom$2$host_data;
    reg  [15:0] wx_rom$2$address;
    wire  [15:0] wx_rom$2$data;
    reg  wx_rom$3$clock;
    reg  wx_rom$3$host_write;
    reg  [23:0] wx_rom$3$host_address;
    reg  [63:0] wx_rom$3$host_data;
    reg  [15:0] wx_rom$3$address;
    wire  [15:0] wx_rom$3$data;
    reg  wy_rom$0$clock;
    reg  wy_rom$0$host_write;
    reg  [23:0] wy_rom$0$host_address;
    reg  [63:0] wy_rom$0$host_data;
    reg  [15:0] wy_rom$0$address;
    wire  [15:0] wy_rom$0$data;
    reg  wy_rom$1$clock;
    reg  wy_rom$1$host_write;
    reg  [23:0] wy_rom$1$host_address;
    reg  [63:0] wy_rom$1$host_data;
    reg  [15:0] wy_rom$1$address;
    wire  [15:0] wy_rom$1$data;
    reg  wy_rom$2$clock;
    reg  wy_rom$2$host_write;
    reg  [23:0] wy_rom$2$host_address;
    reg  [63:0] wy_rom$2$host_data;
    reg  [15:0] wy_rom$2$address;
    wire  [15:0] wy_rom$2$data;
    reg  wy_rom$3$clock;
    reg  wy_rom$3$host_write;
    reg  [23:0] wy_rom$3$host_address;
    reg  [63:0] wy_rom$3$host_data;
    reg  [15:0] wy_rom$3$address;
    wire  [15:0] wy_rom$3$data;
    
    // Local signals
    reg  [15:0] row_stride;
    reg  [31:0] wx_entry;
    reg  [31:0] wy_entry;
    
    // Sub module instances
    top$pipeline$control$templates$wx_rom$0 wx_rom$0(
        .clock(wx_rom$0$clock),
        .host_write(wx_rom$0$host_write),
        .host_address(wx_rom$0$host_address),
        .host_data(wx_rom$0$host_data),
        .address(wx_rom$0$address),
        .data(wx_rom$0$data)
    );
    top$pipeline$control$templates$wx_rom$1 wx_rom$1(
        .clock(wx_rom$1$clock),
        .host_write(wx_rom$1$host_write),
        .host_address(wx_rom$1$host_address),
        .host_data(wx_rom$1$host_data),
        .address(wx_rom$1$address),
        .data(wx_rom$1$data)
    );
    top$pipeline$control$templates$wx_rom$2 wx_rom$2(
        .clock(wx_rom$2$clock),
        .host_write(wx_rom$2$host_write),
        .host_address(wx_rom$2$host_address),
        .host_data(wx_rom$2$host_data),
        .address(wx_rom$2$address),
        .data(wx_rom$2$data)
    );
    top$pipeline$control$templates$wx_rom$3 wx_rom$3(
        .clock(wx_rom$3$clock),
        .host_write(wx_rom$3$host_write),
        .host_address(wx_rom$3$host_address),
        .host_data(wx_rom$3$host_data),
        .address(wx_rom$3$address),
        .data(wx_rom$3$data)
    );
    top$pipeline$control$templates$wy_rom$0 wy_rom$0(
        .clock(wy_rom$0$clock),
        .host_write(wy_rom$0$host_write),
        .host_address(wy_rom$0$host_address),
        .host_data(wy_rom$0$host_data),
        .address(wy_rom$0$address),
        .data(wy_rom$0$data)
    );
    top$pipeline$control$templates$wy_rom$1 wy_rom$1(
        .clock(wy_rom$1$clock),
        .host_write(wy_rom$1$host_write),
        .host_address(wy_rom$1$host_address),
        .host_data(wy_rom$1$host_data),
        .address(wy_rom$1$address),
        .data(wy_rom$1$data)
    );
    top$pipeline$control$templates$wy_rom$2 wy_rom$2(
        .clock(wy_rom$2$clock),
        .host_write(wy_rom$2$host_write),
        .host_address(wy_rom$2$host_address),
        .host_data(wy_rom$2$host_data),
        .address(wy_rom$2$address),
        .data(wy_rom$2$data)
    );
    top$pipeline$control$templates$wy_rom$3 wy_rom$3(
        .clock(wy_rom$3$clock),
        .host_write(wy_rom$3$host_write),
        .host_address(wy_rom$3$host_address),
        .host_data(wy_rom$3$host_data),
        .address(wy_rom$3$address),
        .data(wy_rom$3$data)
    );
    
    // Update code
    always @(*) begin
        row_stride = 'h0;
        if (per_ray) begin
            row_stride = stride;
        end
        wx_entry = ray * row_stride + 32'(segment);
        wy_entry = scanline * row_stride + 32'(segment);
        wx_rom$0$clock = clock;
        wx_rom$0$host_write = host_write;
        wx_rom$0$host_address = host_address;
        wx_rom$0$host_data = host_data;
        wy_rom$0$clock = clock;
        wy_rom$0$host_write = host_write;
        wy_rom$0$host_address = host_address;
        wy_rom$0$host_data = host_data;
        wx_rom$0$address = wx_entry[('h0)+:(16)];
        wy_rom$0$address = wy_entry[('h0)+:(16)];
        wx$0 = wx_rom$0$data;
        wy$0 = wy_rom$0$data;
        wx_rom$1$clock = clock;
        wx_rom$1$host_write = host_write;
        wx_rom$1$host_address = host_address;
        wx_rom$1$host_data = host_data;
        wy_rom$1$clock = clock;
        wy_rom$1$host_write = host_write;
        wy_rom$1$host_address = host_address;
        wy_rom$1$host_data = host_data;
        wx_rom$1$address = wx_entry[('h0)+:(16)];
        wy_rom$1$address = wy_entry[('h0)+:(16)];
        wx$1 = wx_rom$1$data;
        wy$1 = wy_rom$1$data;
        wx_rom$2$clock = clock;
        wx_rom$2$host_write = host_write;
        wx_rom$2$host_address = host_address;
        wx_rom$2$host_data = host_data;
        wy_rom$2$clock = clock;
        wy_rom$2$host_write = host_write;
        wy_rom$2$host_address = host_address;
        wy_rom$2$host_data = host_data;
        wx_rom$2$address = wx_entry[('h0)+:(16)];
        wy_rom$2$address = wy_entry[('h0)+:(16)];
        wx$2 = wx_rom$2$data;
        wy$2 = wy_rom$2$data;
        wx_rom$3$clock = clock;
        wx_rom$3$host_write = host_write;
        wx_rom$3$host_address = host_address;
        wx_rom$3$host_data = host_data;
        wy_rom$3$clock = clock;
        wy_rom$3$host_write = host_write;
        wy_rom$3$host_address = host_address;
        wy_rom$3$host_data = host_data;
        wx_rom$3$address = wx_entry[('h0)+:(16)];
        wy_rom$3$address = wy_entry[('h0)+:(16)];
        wx$3 = wx_rom$3$data;
        wy$3 = wy_rom$3$data;
    end
    
endmodule // top$pipeline$control$templates
module top$pipeline$control$templates$wx_rom$0(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1048576 && host_address < 24'd1048584) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wx_rom$0
module top$pipeline$control$templates$wx_rom$1(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1114112 && host_address < 24'd1114120) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wx_rom$1
module top$pipeline$control$templates$wx_rom$2(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1179648 && host_address < 24'd1179656) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wx_rom$2
module top$pipeline$control$templates$wx_rom$3(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1245184 && host_address < 24'd1245192) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wx_rom$3
module top$pipeline$control$templates$wy_rom$0(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1572864 && host_address < 24'd1572872) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wy_rom$0
module top$pipeline$control$templates$wy_rom$1(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1638400 && host_address < 24'd1638408) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wy_rom$1
module top$pipeline$control$templates$wy_rom$2(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1703936 && host_address < 24'd1703944) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wy_rom$2
module top$pipeline$control$templates$wy_rom$3(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    reg [15:0] mem[7:0];
    integer i;
    initial begin
       for (i = 0; i <= 7; i = i + 1) mem[i] = 16'd0;
    end
    
    always @(*) data = mem[address[2:0]];
    
    always @(posedge clock) begin
       if (host_write && host_address >= 24'd1769472 && host_address < 24'd1769480) begin
          mem[host_address[2:0]] <= host_data[15:0];
       end
    end
endmodule // top$pipeline$control$templates$wy_rom$3
