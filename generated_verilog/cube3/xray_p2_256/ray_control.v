module top$pipeline$control(clock,start,valid,first,unit_valid,unit_first,unit_last,wx$0,wx$1,wy$0,wy$1,in_volume,in_inner);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  valid;
    output reg  first;
    output reg  unit_valid;
    output reg  unit_first;
    output reg  unit_last;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    
    // Constant declarations
    localparam  last_segment = 16'h7f;
    localparam  last_ray = 16'hce;
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
    reg  [7:0] weights$0$address;
    wire  [31:0] weights$0$data;
    reg  [7:0] weights$1$address;
    wire  [31:0] weights$1$data;
    reg  [7:0] bounds$0$address;
    wire  [63:0] bounds$0$data;
    reg  [7:0] bounds$1$address;
    wire  [63:0] bounds$1$data;
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    
    // Local signals
    reg  [15:0] unit_segment;
    reg  [15:0] unit_ray;
    reg  [15:0] unit_scanline;
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
        .data_out(late$data_out)
    );
    top$pipeline$control$weights$0 weights$0(
        .address(weights$0$address),
        .data(weights$0$data)
    );
    top$pipeline$control$weights$1 weights$1(
        .address(weights$1$address),
        .data(weights$1$data)
    );
    top$pipeline$control$bounds$0 bounds$0(
        .address(bounds$0$address),
        .data(bounds$0$data)
    );
    top$pipeline$control$bounds$1 bounds$1(
        .address(bounds$1$address),
        .data(bounds$1$data)
    );
    top$pipeline$control$inner$0 inner$0(
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .address(inner$1$address),
        .data(inner$1$data)
    );
    
    // Update code
    always @(*) begin
        segment$clock = clock;
        ray$clock = clock;
        scanline$clock = clock;
        segment$d = segment$q;
        ray$d = ray$q;
        scanline$d = scanline$q;
        late$clock = clock;
        late$write_enable = 1'b1;
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
        weights$0$address = unit_segment[('h0)+:(8)];
        bounds$0$address = unit_segment[('h0)+:(8)];
        wx$0 = weights$0$data[('h0)+:(16)];
        wy$0 = weights$0$data[('h10)+:(16)];
        if ((unit_ray >= bounds$0$data[('h0)+:(16)]) & (unit_ray <= bounds$0$data[('h10)+:(16)]) & (unit_scanline >= bounds$0$data[('h20)+:(16)]) & (unit_scanline <= bounds$0$data[('h30)+:(16)])) begin
            lane_in$0 = lane_bit$0;
        end
        inner$0$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$0$data[('h0)+:(16)]) & (unit_ray <= inner$0$data[('h10)+:(16)]) & (unit_scanline >= inner$0$data[('h20)+:(16)]) & (unit_scanline <= inner$0$data[('h30)+:(16)])) begin
            lane_inner$0 = lane_bit$0;
        end
        weights$1$address = unit_segment[('h0)+:(8)];
        bounds$1$address = unit_segment[('h0)+:(8)];
        wx$1 = weights$1$data[('h0)+:(16)];
        wy$1 = weights$1$data[('h10)+:(16)];
        if ((unit_ray >= bounds$1$data[('h0)+:(16)]) & (unit_ray <= bounds$1$data[('h10)+:(16)]) & (unit_scanline >= bounds$1$data[('h20)+:(16)]) & (unit_scanline <= bounds$1$data[('h30)+:(16)])) begin
            lane_in$1 = lane_bit$1;
        end
        inner$1$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$1$data[('h0)+:(16)]) & (unit_ray <= inner$1$data[('h10)+:(16)]) & (unit_scanline >= inner$1$data[('h20)+:(16)]) & (unit_scanline <= inner$1$data[('h30)+:(16)])) begin
            lane_inner$1 = lane_bit$1;
        end
        in_volume = lane_in$0 | lane_in$1 | lane_in$2 | lane_in$3 | lane_in$4 | lane_in$5 | lane_in$6 | lane_in$7;
        in_inner = lane_inner$0 | lane_inner$1 | lane_inner$2 | lane_inner$3 | lane_inner$4 | lane_inner$5 | lane_inner$6 | lane_inner$7;
    end
    
endmodule // top$pipeline$control
module top$pipeline$control$bounds$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h19c009d006f0002;
      8'h1: data = 64'h19a009c006f0003;
      8'h2: data = 64'h199009b00700004;
      8'h3: data = 64'h198009a00710005;
      8'h4: data = 64'h197009900710005;
      8'h5: data = 64'h195009700720006;
      8'h6: data = 64'h194009600730007;
      8'h7: data = 64'h193009500740008;
      8'h8: data = 64'h192009400740008;
      8'h9: data = 64'h190009200750009;
      8'ha: data = 64'h18f00910076000a;
      8'hb: data = 64'h18e00900076000a;
      8'hc: data = 64'h18d008f0077000b;
      8'hd: data = 64'h18c008e0078000c;
      8'he: data = 64'h18a008c0079000d;
      8'hf: data = 64'h189008b0079000d;
      8'h10: data = 64'h188008a007a000e;
      8'h11: data = 64'h1870089007b000f;
      8'h12: data = 64'h1850087007c0010;
      8'h13: data = 64'h1840086007c0010;
      8'h14: data = 64'h1830085007d0011;
      8'h15: data = 64'h1820084007e0012;
      8'h16: data = 64'h1810083007e0012;
      8'h17: data = 64'h17f0081007f0013;
      8'h18: data = 64'h17e008000800014;
      8'h19: data = 64'h17d007f00810015;
      8'h1a: data = 64'h17c007e00810015;
      8'h1b: data = 64'h17a007c00820016;
      8'h1c: data = 64'h179007b00830017;
      8'h1d: data = 64'h178007a00840018;
      8'h1e: data = 64'h177007900840018;
      8'h1f: data = 64'h175007700850019;
      8'h20: data = 64'h17400760086001a;
      8'h21: data = 64'h17300750086001a;
      8'h22: data = 64'h17200740087001b;
      8'h23: data = 64'h17100730088001c;
      8'h24: data = 64'h16f00710089001d;
      8'h25: data = 64'h16e00700089001d;
      8'h26: data = 64'h16d006f008a001e;
      8'h27: data = 64'h16c006e008b001f;
      8'h28: data = 64'h16a006c008c0020;
      8'h29: data = 64'h169006b008c0020;
      8'h2a: data = 64'h168006a008d0021;
      8'h2b: data = 64'h1670069008e0022;
      8'h2c: data = 64'h1660068008e0022;
      8'h2d: data = 64'h1640066008f0023;
      8'h2e: data = 64'h163006500900024;
      8'h2f: data = 64'h162006400910025;
      8'h30: data = 64'h161006300910025;
      8'h31: data = 64'h15f006100920026;
      8'h32: data = 64'h15e006000930027;
      8'h33: data = 64'h15d005f00940028;
      8'h34: data = 64'h15c005e00940028;
      8'h35: data = 64'h15a005c00950029;
      8'h36: data = 64'h159005b0096002a;
      8'h37: data = 64'h158005a0096002a;
      8'h38: data = 64'h15700590097002b;
      8'h39: data = 64'h15600580098002c;
      8'h3a: data = 64'h15400560099002d;
      8'h3b: data = 64'h15300550099002d;
      8'h3c: data = 64'h1520054009a002e;
      8'h3d: data = 64'h1510053009b002f;
      8'h3e: data = 64'h14f0051009c0030;
      8'h3f: data = 64'h14e0050009c0030;
      8'h40: data = 64'h14d004f009d0031;
      8'h41: data = 64'h14c004e009e0032;
      8'h42: data = 64'h14b004d009e0032;
      8'h43: data = 64'h149004b009f0033;
      8'h44: data = 64'h148004a00a00034;
      8'h45: data = 64'h147004900a10035;
      8'h46: data = 64'h146004800a10035;
      8'h47: data = 64'h144004600a20036;
      8'h48: data = 64'h143004500a30037;
      8'h49: data = 64'h142004400a40038;
      8'h4a: data = 64'h141004300a40038;
      8'h4b: data = 64'h140004200a50039;
      8'h4c: data = 64'h13e004000a6003a;
      8'h4d: data = 64'h13d003f00a6003a;
      8'h4e: data = 64'h13c003e00a7003b;
      8'h4f: data = 64'h13b003d00a8003c;
      8'h50: data = 64'h139003b00a9003d;
      8'h51: data = 64'h138003a00a9003d;
      8'h52: data = 64'h137003900aa003e;
      8'h53: data = 64'h136003800ab003f;
      8'h54: data = 64'h134003600ac0040;
      8'h55: data = 64'h133003500ac0040;
      8'h56: data = 64'h132003400ad0041;
      8'h57: data = 64'h131003300ae0042;
      8'h58: data = 64'h130003200ae0042;
      8'h59: data = 64'h12e003000af0043;
      8'h5a: data = 64'h12d002f00b00044;
      8'h5b: data = 64'h12c002e00b10045;
      8'h5c: data = 64'h12b002d00b10045;
      8'h5d: data = 64'h129002b00b20046;
      8'h5e: data = 64'h128002a00b30047;
      8'h5f: data = 64'h127002900b40048;
      8'h60: data = 64'h126002800b40048;
      8'h61: data = 64'h125002700b50049;
      8'h62: data = 64'h123002500b6004a;
      8'h63: data = 64'h122002400b6004a;
      8'h64: data = 64'h121002300b7004b;
      8'h65: data = 64'h120002200b8004c;
      8'h66: data = 64'h11e002000b9004d;
      8'h67: data = 64'h11d001f00b9004d;
      8'h68: data = 64'h11c001e00ba004e;
      8'h69: data = 64'h11b001d00bb004f;
      8'h6a: data = 64'h119001b00bc0050;
      8'h6b: data = 64'h118001a00bc0050;
      8'h6c: data = 64'h117001900bd0051;
      8'h6d: data = 64'h116001800be0052;
      8'h6e: data = 64'h115001700be0052;
      8'h6f: data = 64'h113001500bf0053;
      8'h70: data = 64'h112001400c00054;
      8'h71: data = 64'h111001300c10055;
      8'h72: data = 64'h110001200c10055;
      8'h73: data = 64'h10e001000c20056;
      8'h74: data = 64'h10d000f00c30057;
      8'h75: data = 64'h10c000e00c40058;
      8'h76: data = 64'h10b000d00c40058;
      8'h77: data = 64'h10a000c00c50059;
      8'h78: data = 64'h108000a00c6005a;
      8'h79: data = 64'h107000900c6005a;
      8'h7a: data = 64'h106000800c7005b;
      8'h7b: data = 64'h105000700c8005c;
      8'h7c: data = 64'h103000500c9005d;
      8'h7d: data = 64'h102000400c9005d;
      8'h7e: data = 64'h101000300ca005e;
      8'h7f: data = 64'h100000200cb005f;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$0
module top$pipeline$control$bounds$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h19b009d006f0003;
      8'h1: data = 64'h19a009c00700004;
      8'h2: data = 64'h198009a00700004;
      8'h3: data = 64'h197009900710005;
      8'h4: data = 64'h196009800720006;
      8'h5: data = 64'h195009700720006;
      8'h6: data = 64'h194009600730007;
      8'h7: data = 64'h192009400740008;
      8'h8: data = 64'h191009300750009;
      8'h9: data = 64'h190009200750009;
      8'ha: data = 64'h18f00910076000a;
      8'hb: data = 64'h18d008f0077000b;
      8'hc: data = 64'h18c008e0078000c;
      8'hd: data = 64'h18b008d0078000c;
      8'he: data = 64'h18a008c0079000d;
      8'hf: data = 64'h188008a007a000e;
      8'h10: data = 64'h1870089007a000e;
      8'h11: data = 64'h1860088007b000f;
      8'h12: data = 64'h1850087007c0010;
      8'h13: data = 64'h1840086007d0011;
      8'h14: data = 64'h1820084007d0011;
      8'h15: data = 64'h1810083007e0012;
      8'h16: data = 64'h1800082007f0013;
      8'h17: data = 64'h17f008100800014;
      8'h18: data = 64'h17d007f00800014;
      8'h19: data = 64'h17c007e00810015;
      8'h1a: data = 64'h17b007d00820016;
      8'h1b: data = 64'h17a007c00820016;
      8'h1c: data = 64'h179007b00830017;
      8'h1d: data = 64'h177007900840018;
      8'h1e: data = 64'h176007800850019;
      8'h1f: data = 64'h175007700850019;
      8'h20: data = 64'h17400760086001a;
      8'h21: data = 64'h17200740087001b;
      8'h22: data = 64'h17100730088001c;
      8'h23: data = 64'h17000720088001c;
      8'h24: data = 64'h16f00710089001d;
      8'h25: data = 64'h16e0070008a001e;
      8'h26: data = 64'h16c006e008a001e;
      8'h27: data = 64'h16b006d008b001f;
      8'h28: data = 64'h16a006c008c0020;
      8'h29: data = 64'h169006b008d0021;
      8'h2a: data = 64'h1670069008d0021;
      8'h2b: data = 64'h1660068008e0022;
      8'h2c: data = 64'h1650067008f0023;
      8'h2d: data = 64'h164006600900024;
      8'h2e: data = 64'h162006400900024;
      8'h2f: data = 64'h161006300910025;
      8'h30: data = 64'h160006200920026;
      8'h31: data = 64'h15f006100920026;
      8'h32: data = 64'h15e006000930027;
      8'h33: data = 64'h15c005e00940028;
      8'h34: data = 64'h15b005d00950029;
      8'h35: data = 64'h15a005c00950029;
      8'h36: data = 64'h159005b0096002a;
      8'h37: data = 64'h15700590097002b;
      8'h38: data = 64'h15600580098002c;
      8'h39: data = 64'h15500570098002c;
      8'h3a: data = 64'h15400560099002d;
      8'h3b: data = 64'h1530055009a002e;
      8'h3c: data = 64'h1510053009a002e;
      8'h3d: data = 64'h1500052009b002f;
      8'h3e: data = 64'h14f0051009c0030;
      8'h3f: data = 64'h14e0050009d0031;
      8'h40: data = 64'h14c004e009d0031;
      8'h41: data = 64'h14b004d009e0032;
      8'h42: data = 64'h14a004c009f0033;
      8'h43: data = 64'h149004b00a00034;
      8'h44: data = 64'h147004900a00034;
      8'h45: data = 64'h146004800a10035;
      8'h46: data = 64'h145004700a20036;
      8'h47: data = 64'h144004600a20036;
      8'h48: data = 64'h143004500a30037;
      8'h49: data = 64'h141004300a40038;
      8'h4a: data = 64'h140004200a50039;
      8'h4b: data = 64'h13f004100a50039;
      8'h4c: data = 64'h13e004000a6003a;
      8'h4d: data = 64'h13c003e00a7003b;
      8'h4e: data = 64'h13b003d00a8003c;
      8'h4f: data = 64'h13a003c00a8003c;
      8'h50: data = 64'h139003b00a9003d;
      8'h51: data = 64'h138003a00aa003e;
      8'h52: data = 64'h136003800aa003e;
      8'h53: data = 64'h135003700ab003f;
      8'h54: data = 64'h134003600ac0040;
      8'h55: data = 64'h133003500ad0041;
      8'h56: data = 64'h131003300ad0041;
      8'h57: data = 64'h130003200ae0042;
      8'h58: data = 64'h12f003100af0043;
      8'h59: data = 64'h12e003000b00044;
      8'h5a: data = 64'h12c002e00b00044;
      8'h5b: data = 64'h12b002d00b10045;
      8'h5c: data = 64'h12a002c00b20046;
      8'h5d: data = 64'h129002b00b20046;
      8'h5e: data = 64'h128002a00b30047;
      8'h5f: data = 64'h126002800b40048;
      8'h60: data = 64'h125002700b50049;
      8'h61: data = 64'h124002600b50049;
      8'h62: data = 64'h123002500b6004a;
      8'h63: data = 64'h121002300b7004b;
      8'h64: data = 64'h120002200b8004c;
      8'h65: data = 64'h11f002100b8004c;
      8'h66: data = 64'h11e002000b9004d;
      8'h67: data = 64'h11d001f00ba004e;
      8'h68: data = 64'h11b001d00ba004e;
      8'h69: data = 64'h11a001c00bb004f;
      8'h6a: data = 64'h119001b00bc0050;
      8'h6b: data = 64'h118001a00bd0051;
      8'h6c: data = 64'h116001800bd0051;
      8'h6d: data = 64'h115001700be0052;
      8'h6e: data = 64'h114001600bf0053;
      8'h6f: data = 64'h113001500c00054;
      8'h70: data = 64'h112001400c00054;
      8'h71: data = 64'h110001200c10055;
      8'h72: data = 64'h10f001100c20056;
      8'h73: data = 64'h10e001000c20056;
      8'h74: data = 64'h10d000f00c30057;
      8'h75: data = 64'h10b000d00c40058;
      8'h76: data = 64'h10a000c00c50059;
      8'h77: data = 64'h109000b00c50059;
      8'h78: data = 64'h108000a00c6005a;
      8'h79: data = 64'h106000800c7005b;
      8'h7a: data = 64'h105000700c8005c;
      8'h7b: data = 64'h104000600c8005c;
      8'h7c: data = 64'h103000500c9005d;
      8'h7d: data = 64'h102000400ca005e;
      8'h7e: data = 64'h100000200ca005e;
      8'h7f: data = 64'hff000100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$1
module top$pipeline$control$inner$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      8'h8: data = 64'h100000001;
      8'h9: data = 64'h100000001;
      8'ha: data = 64'h100000001;
      8'hb: data = 64'h100000001;
      8'hc: data = 64'h100000001;
      8'hd: data = 64'h100000001;
      8'he: data = 64'h100000001;
      8'hf: data = 64'h100000001;
      8'h10: data = 64'h100000001;
      8'h11: data = 64'h100000001;
      8'h12: data = 64'h100000001;
      8'h13: data = 64'h100000001;
      8'h14: data = 64'h100000001;
      8'h15: data = 64'h100000001;
      8'h16: data = 64'h100000001;
      8'h17: data = 64'h100000001;
      8'h18: data = 64'h100000001;
      8'h19: data = 64'h100000001;
      8'h1a: data = 64'h100000001;
      8'h1b: data = 64'h100000001;
      8'h1c: data = 64'h100000001;
      8'h1d: data = 64'h100000001;
      8'h1e: data = 64'h100000001;
      8'h1f: data = 64'h100000001;
      8'h20: data = 64'h100000001;
      8'h21: data = 64'h100000001;
      8'h22: data = 64'h100000001;
      8'h23: data = 64'h100000001;
      8'h24: data = 64'h100000001;
      8'h25: data = 64'h100000001;
      8'h26: data = 64'h100000001;
      8'h27: data = 64'h100000001;
      8'h28: data = 64'h100000001;
      8'h29: data = 64'h100000001;
      8'h2a: data = 64'h100000001;
      8'h2b: data = 64'h100000001;
      8'h2c: data = 64'h100000001;
      8'h2d: data = 64'h100000001;
      8'h2e: data = 64'h100000001;
      8'h2f: data = 64'h100000001;
      8'h30: data = 64'h100000001;
      8'h31: data = 64'h100000001;
      8'h32: data = 64'h100000001;
      8'h33: data = 64'h100000001;
      8'h34: data = 64'h100000001;
      8'h35: data = 64'h100000001;
      8'h36: data = 64'h100000001;
      8'h37: data = 64'h100000001;
      8'h38: data = 64'h100000001;
      8'h39: data = 64'h100000001;
      8'h3a: data = 64'h100000001;
      8'h3b: data = 64'h100000001;
      8'h3c: data = 64'h100000001;
      8'h3d: data = 64'h100000001;
      8'h3e: data = 64'h100000001;
      8'h3f: data = 64'h100000001;
      8'h40: data = 64'h100000001;
      8'h41: data = 64'h100000001;
      8'h42: data = 64'h100000001;
      8'h43: data = 64'h100000001;
      8'h44: data = 64'h100000001;
      8'h45: data = 64'h100000001;
      8'h46: data = 64'h100000001;
      8'h47: data = 64'h100000001;
      8'h48: data = 64'h100000001;
      8'h49: data = 64'h100000001;
      8'h4a: data = 64'h100000001;
      8'h4b: data = 64'h100000001;
      8'h4c: data = 64'h100000001;
      8'h4d: data = 64'h100000001;
      8'h4e: data = 64'h100000001;
      8'h4f: data = 64'h100000001;
      8'h50: data = 64'h100000001;
      8'h51: data = 64'h100000001;
      8'h52: data = 64'h100000001;
      8'h53: data = 64'h100000001;
      8'h54: data = 64'h100000001;
      8'h55: data = 64'h100000001;
      8'h56: data = 64'h100000001;
      8'h57: data = 64'h100000001;
      8'h58: data = 64'h100000001;
      8'h59: data = 64'h100000001;
      8'h5a: data = 64'h100000001;
      8'h5b: data = 64'h100000001;
      8'h5c: data = 64'h100000001;
      8'h5d: data = 64'h100000001;
      8'h5e: data = 64'h100000001;
      8'h5f: data = 64'h100000001;
      8'h60: data = 64'h100000001;
      8'h61: data = 64'h100000001;
      8'h62: data = 64'h100000001;
      8'h63: data = 64'h100000001;
      8'h64: data = 64'h100000001;
      8'h65: data = 64'h100000001;
      8'h66: data = 64'h100000001;
      8'h67: data = 64'h100000001;
      8'h68: data = 64'h100000001;
      8'h69: data = 64'h100000001;
      8'h6a: data = 64'h100000001;
      8'h6b: data = 64'h100000001;
      8'h6c: data = 64'h100000001;
      8'h6d: data = 64'h100000001;
      8'h6e: data = 64'h100000001;
      8'h6f: data = 64'h100000001;
      8'h70: data = 64'h100000001;
      8'h71: data = 64'h100000001;
      8'h72: data = 64'h100000001;
      8'h73: data = 64'h100000001;
      8'h74: data = 64'h100000001;
      8'h75: data = 64'h100000001;
      8'h76: data = 64'h100000001;
      8'h77: data = 64'h100000001;
      8'h78: data = 64'h100000001;
      8'h79: data = 64'h100000001;
      8'h7a: data = 64'h100000001;
      8'h7b: data = 64'h100000001;
      8'h7c: data = 64'h100000001;
      8'h7d: data = 64'h100000001;
      8'h7e: data = 64'h100000001;
      8'h7f: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$0
module top$pipeline$control$inner$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'h100000001;
      8'h1: data = 64'h100000001;
      8'h2: data = 64'h100000001;
      8'h3: data = 64'h100000001;
      8'h4: data = 64'h100000001;
      8'h5: data = 64'h100000001;
      8'h6: data = 64'h100000001;
      8'h7: data = 64'h100000001;
      8'h8: data = 64'h100000001;
      8'h9: data = 64'h100000001;
      8'ha: data = 64'h100000001;
      8'hb: data = 64'h100000001;
      8'hc: data = 64'h100000001;
      8'hd: data = 64'h100000001;
      8'he: data = 64'h100000001;
      8'hf: data = 64'h100000001;
      8'h10: data = 64'h100000001;
      8'h11: data = 64'h100000001;
      8'h12: data = 64'h100000001;
      8'h13: data = 64'h100000001;
      8'h14: data = 64'h100000001;
      8'h15: data = 64'h100000001;
      8'h16: data = 64'h100000001;
      8'h17: data = 64'h100000001;
      8'h18: data = 64'h100000001;
      8'h19: data = 64'h100000001;
      8'h1a: data = 64'h100000001;
      8'h1b: data = 64'h100000001;
      8'h1c: data = 64'h100000001;
      8'h1d: data = 64'h100000001;
      8'h1e: data = 64'h100000001;
      8'h1f: data = 64'h100000001;
      8'h20: data = 64'h100000001;
      8'h21: data = 64'h100000001;
      8'h22: data = 64'h100000001;
      8'h23: data = 64'h100000001;
      8'h24: data = 64'h100000001;
      8'h25: data = 64'h100000001;
      8'h26: data = 64'h100000001;
      8'h27: data = 64'h100000001;
      8'h28: data = 64'h100000001;
      8'h29: data = 64'h100000001;
      8'h2a: data = 64'h100000001;
      8'h2b: data = 64'h100000001;
      8'h2c: data = 64'h100000001;
      8'h2d: data = 64'h100000001;
      8'h2e: data = 64'h100000001;
      8'h2f: data = 64'h100000001;
      8'h30: data = 64'h100000001;
      8'h31: data = 64'h100000001;
      8'h32: data = 64'h100000001;
      8'h33: data = 64'h100000001;
      8'h34: data = 64'h100000001;
      8'h35: data = 64'h100000001;
      8'h36: data = 64'h100000001;
      8'h37: data = 64'h100000001;
      8'h38: data = 64'h100000001;
      8'h39: data = 64'h100000001;
      8'h3a: data = 64'h100000001;
      8'h3b: data = 64'h100000001;
      8'h3c: data = 64'h100000001;
      8'h3d: data = 64'h100000001;
      8'h3e: data = 64'h100000001;
      8'h3f: data = 64'h100000001;
      8'h40: data = 64'h100000001;
      8'h41: data = 64'h100000001;
      8'h42: data = 64'h100000001;
      8'h43: data = 64'h100000001;
      8'h44: data = 64'h100000001;
      8'h45: data = 64'h100000001;
      8'h46: data = 64'h100000001;
      8'h47: data = 64'h100000001;
      8'h48: data = 64'h100000001;
      8'h49: data = 64'h100000001;
      8'h4a: data = 64'h100000001;
      8'h4b: data = 64'h100000001;
      8'h4c: data = 64'h100000001;
      8'h4d: data = 64'h100000001;
      8'h4e: data = 64'h100000001;
      8'h4f: data = 64'h100000001;
      8'h50: data = 64'h100000001;
      8'h51: data = 64'h100000001;
      8'h52: data = 64'h100000001;
      8'h53: data = 64'h100000001;
      8'h54: data = 64'h100000001;
      8'h55: data = 64'h100000001;
      8'h56: data = 64'h100000001;
      8'h57: data = 64'h100000001;
      8'h58: data = 64'h100000001;
      8'h59: data = 64'h100000001;
      8'h5a: data = 64'h100000001;
      8'h5b: data = 64'h100000001;
      8'h5c: data = 64'h100000001;
      8'h5d: data = 64'h100000001;
      8'h5e: data = 64'h100000001;
      8'h5f: data = 64'h100000001;
      8'h60: data = 64'h100000001;
      8'h61: data = 64'h100000001;
      8'h62: data = 64'h100000001;
      8'h63: data = 64'h100000001;
      8'h64: data = 64'h100000001;
      8'h65: data = 64'h100000001;
      8'h66: data = 64'h100000001;
      8'h67: data = 64'h100000001;
      8'h68: data = 64'h100000001;
      8'h69: data = 64'h100000001;
      8'h6a: data = 64'h100000001;
      8'h6b: data = 64'h100000001;
      8'h6c: data = 64'h100000001;
      8'h6d: data = 64'h100000001;
      8'h6e: data = 64'h100000001;
      8'h6f: data = 64'h100000001;
      8'h70: data = 64'h100000001;
      8'h71: data = 64'h100000001;
      8'h72: data = 64'h100000001;
      8'h73: data = 64'h100000001;
      8'h74: data = 64'h100000001;
      8'h75: data = 64'h100000001;
      8'h76: data = 64'h100000001;
      8'h77: data = 64'h100000001;
      8'h78: data = 64'h100000001;
      8'h79: data = 64'h100000001;
      8'h7a: data = 64'h100000001;
      8'h7b: data = 64'h100000001;
      8'h7c: data = 64'h100000001;
      8'h7d: data = 64'h100000001;
      8'h7e: data = 64'h100000001;
      8'h7f: data = 64'h100000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$late(clock,data_in,write_enable,data_out);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    
    // Constant declarations
    localparam  last = 16'h80;
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
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$late$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$late$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$late$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    always @(*) begin
        ptr$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        next = ptr$q + 'h1;
        if (ptr$q == last) begin
            next = 'h0;
        end
        ptr$d = next;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = next;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single) begin
            data_out = one$q;
        end
        else begin
            data_out = ram$read_data;
        end
    end
    
endmodule // top$pipeline$control$late
module top$pipeline$control$late$one(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$one
module top$pipeline$control$late$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$ptr
module top$pipeline$control$late$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [63:0] mem[128:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[7:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$late$ram
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
module top$pipeline$control$weights$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h5d;
      8'h1: data = 'h3a00a3;
      8'h2: data = 'h17008c;
      8'h3: data = 'h5100d2;
      8'h4: data = 'h8b0075;
      8'h5: data = 'h22005e;
      8'h6: data = 'h5c00a4;
      8'h7: data = 'h3900ea;
      8'h8: data = 'h73008d;
      8'h9: data = 'ha0076;
      8'ha: data = 'h4400bc;
      8'hb: data = 'h21005f;
      8'hc: data = 'h5b00a5;
      8'hd: data = 'h95008e;
      8'he: data = 'h2c00d4;
      8'hf: data = 'h90077;
      8'h10: data = 'h430060;
      8'h11: data = 'h7d00a6;
      8'h12: data = 'h1400ec;
      8'h13: data = 'h4e008f;
      8'h14: data = 'h2b0078;
      8'h15: data = 'h6500be;
      8'h16: data = 'h9f0061;
      8'h17: data = 'h3600a7;
      8'h18: data = 'h130090;
      8'h19: data = 'h4d00d6;
      8'h1a: data = 'h870079;
      8'h1b: data = 'h1e0062;
      8'h1c: data = 'h5800a8;
      8'h1d: data = 'h3500ee;
      8'h1e: data = 'h6f0091;
      8'h1f: data = 'h6007a;
      8'h20: data = 'h4000c0;
      8'h21: data = 'h1d0063;
      8'h22: data = 'h5700a9;
      8'h23: data = 'h910092;
      8'h24: data = 'h2800d8;
      8'h25: data = 'h62007b;
      8'h26: data = 'h3f0064;
      8'h27: data = 'h7900aa;
      8'h28: data = 'h1000f0;
      8'h29: data = 'h4a0093;
      8'h2a: data = 'h27007c;
      8'h2b: data = 'h6100c2;
      8'h2c: data = 'h9b0065;
      8'h2d: data = 'h3200ab;
      8'h2e: data = 'hf0094;
      8'h2f: data = 'h4900da;
      8'h30: data = 'h83007d;
      8'h31: data = 'h1a0066;
      8'h32: data = 'h5400ac;
      8'h33: data = 'h3100f2;
      8'h34: data = 'h6b0095;
      8'h35: data = 'h2007e;
      8'h36: data = 'h3c00c4;
      8'h37: data = 'h190067;
      8'h38: data = 'h5300ad;
      8'h39: data = 'h8d0096;
      8'h3a: data = 'h2400dc;
      8'h3b: data = 'h5e007f;
      8'h3c: data = 'h3b0068;
      8'h3d: data = 'h7500ae;
      8'h3e: data = 'hc00f4;
      8'h3f: data = 'h460097;
      8'h40: data = 'h230080;
      8'h41: data = 'h5d00c6;
      8'h42: data = 'h970069;
      8'h43: data = 'h2e00af;
      8'h44: data = 'hb0098;
      8'h45: data = 'h4500de;
      8'h46: data = 'h7f0081;
      8'h47: data = 'h16006a;
      8'h48: data = 'h5000b0;
      8'h49: data = 'h2d00f6;
      8'h4a: data = 'h670099;
      8'h4b: data = 'ha10082;
      8'h4c: data = 'h3800c8;
      8'h4d: data = 'h15006b;
      8'h4e: data = 'h4f00b1;
      8'h4f: data = 'h89009a;
      8'h50: data = 'h2000e0;
      8'h51: data = 'h5a0083;
      8'h52: data = 'h37006c;
      8'h53: data = 'h7100b2;
      8'h54: data = 'h800f8;
      8'h55: data = 'h42009b;
      8'h56: data = 'h1f0084;
      8'h57: data = 'h5900ca;
      8'h58: data = 'h93006d;
      8'h59: data = 'h2a00b3;
      8'h5a: data = 'h7009c;
      8'h5b: data = 'h4100e2;
      8'h5c: data = 'h7b0085;
      8'h5d: data = 'h12006e;
      8'h5e: data = 'h4c00b4;
      8'h5f: data = 'h2900fa;
      8'h60: data = 'h63009d;
      8'h61: data = 'h9d0086;
      8'h62: data = 'h3400cc;
      8'h63: data = 'h11006f;
      8'h64: data = 'h4b00b5;
      8'h65: data = 'h85009e;
      8'h66: data = 'h1c00e4;
      8'h67: data = 'h560087;
      8'h68: data = 'h330070;
      8'h69: data = 'h6d00b6;
      8'h6a: data = 'h400fc;
      8'h6b: data = 'h3e009f;
      8'h6c: data = 'h1b0088;
      8'h6d: data = 'h5500ce;
      8'h6e: data = 'h8f0071;
      8'h6f: data = 'h2600b7;
      8'h70: data = 'h6000a0;
      8'h71: data = 'h3d00e6;
      8'h72: data = 'h770089;
      8'h73: data = 'he0072;
      8'h74: data = 'h4800b8;
      8'h75: data = 'h2500fe;
      8'h76: data = 'h5f00a1;
      8'h77: data = 'h99008a;
      8'h78: data = 'h3000d0;
      8'h79: data = 'hd0073;
      8'h7a: data = 'h4700b9;
      8'h7b: data = 'h8100a2;
      8'h7c: data = 'h1800e8;
      8'h7d: data = 'h52008b;
      8'h7e: data = 'h2f0074;
      8'h7f: data = 'h6900ba;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$0
module top$pipeline$control$weights$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [31:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 'h4000a3;
      8'h1: data = 'h7a00e9;
      8'h2: data = 'h11008c;
      8'h3: data = 'h4b0075;
      8'h4: data = 'h2800bb;
      8'h5: data = 'h62005e;
      8'h6: data = 'h9c00a4;
      8'h7: data = 'h33008d;
      8'h8: data = 'h1000d3;
      8'h9: data = 'h4a0076;
      8'ha: data = 'h84005f;
      8'hb: data = 'h1b00a5;
      8'hc: data = 'h5500eb;
      8'hd: data = 'h32008e;
      8'he: data = 'h6c0077;
      8'hf: data = 'h300bd;
      8'h10: data = 'h3d0060;
      8'h11: data = 'h1a00a6;
      8'h12: data = 'h54008f;
      8'h13: data = 'h8e00d5;
      8'h14: data = 'h250078;
      8'h15: data = 'h5f0061;
      8'h16: data = 'h3c00a7;
      8'h17: data = 'h7600ed;
      8'h18: data = 'hd0090;
      8'h19: data = 'h470079;
      8'h1a: data = 'h2400bf;
      8'h1b: data = 'h5e0062;
      8'h1c: data = 'h9800a8;
      8'h1d: data = 'h2f0091;
      8'h1e: data = 'hc00d7;
      8'h1f: data = 'h46007a;
      8'h20: data = 'h800063;
      8'h21: data = 'h1700a9;
      8'h22: data = 'h5100ef;
      8'h23: data = 'h2e0092;
      8'h24: data = 'h68007b;
      8'h25: data = 'ha200c1;
      8'h26: data = 'h390064;
      8'h27: data = 'h1600aa;
      8'h28: data = 'h500093;
      8'h29: data = 'h8a00d9;
      8'h2a: data = 'h21007c;
      8'h2b: data = 'h5b0065;
      8'h2c: data = 'h3800ab;
      8'h2d: data = 'h7200f1;
      8'h2e: data = 'h90094;
      8'h2f: data = 'h43007d;
      8'h30: data = 'h2000c3;
      8'h31: data = 'h5a0066;
      8'h32: data = 'h9400ac;
      8'h33: data = 'h2b0095;
      8'h34: data = 'h800db;
      8'h35: data = 'h42007e;
      8'h36: data = 'h7c0067;
      8'h37: data = 'h1300ad;
      8'h38: data = 'h4d00f3;
      8'h39: data = 'h2a0096;
      8'h3a: data = 'h64007f;
      8'h3b: data = 'h9e00c5;
      8'h3c: data = 'h350068;
      8'h3d: data = 'h1200ae;
      8'h3e: data = 'h4c0097;
      8'h3f: data = 'h8600dd;
      8'h40: data = 'h1d0080;
      8'h41: data = 'h570069;
      8'h42: data = 'h3400af;
      8'h43: data = 'h6e00f5;
      8'h44: data = 'h50098;
      8'h45: data = 'h3f0081;
      8'h46: data = 'h1c00c7;
      8'h47: data = 'h56006a;
      8'h48: data = 'h9000b0;
      8'h49: data = 'h270099;
      8'h4a: data = 'h6100df;
      8'h4b: data = 'h3e0082;
      8'h4c: data = 'h78006b;
      8'h4d: data = 'hf00b1;
      8'h4e: data = 'h4900f7;
      8'h4f: data = 'h26009a;
      8'h50: data = 'h600083;
      8'h51: data = 'h9a00c9;
      8'h52: data = 'h31006c;
      8'h53: data = 'he00b2;
      8'h54: data = 'h48009b;
      8'h55: data = 'h8200e1;
      8'h56: data = 'h190084;
      8'h57: data = 'h53006d;
      8'h58: data = 'h3000b3;
      8'h59: data = 'h6a00f9;
      8'h5a: data = 'h1009c;
      8'h5b: data = 'h3b0085;
      8'h5c: data = 'h1800cb;
      8'h5d: data = 'h52006e;
      8'h5e: data = 'h8c00b4;
      8'h5f: data = 'h23009d;
      8'h60: data = 'h5d00e3;
      8'h61: data = 'h3a0086;
      8'h62: data = 'h74006f;
      8'h63: data = 'hb00b5;
      8'h64: data = 'h4500fb;
      8'h65: data = 'h22009e;
      8'h66: data = 'h5c0087;
      8'h67: data = 'h9600cd;
      8'h68: data = 'h2d0070;
      8'h69: data = 'ha00b6;
      8'h6a: data = 'h44009f;
      8'h6b: data = 'h7e00e5;
      8'h6c: data = 'h150088;
      8'h6d: data = 'h4f0071;
      8'h6e: data = 'h2c00b7;
      8'h6f: data = 'h6600fd;
      8'h70: data = 'ha000a0;
      8'h71: data = 'h370089;
      8'h72: data = 'h1400cf;
      8'h73: data = 'h4e0072;
      8'h74: data = 'h8800b8;
      8'h75: data = 'h1f00a1;
      8'h76: data = 'h5900e7;
      8'h77: data = 'h36008a;
      8'h78: data = 'h700073;
      8'h79: data = 'h700b9;
      8'h7a: data = 'h4100ff;
      8'h7b: data = 'h1e00a2;
      8'h7c: data = 'h58008b;
      8'h7d: data = 'h9200d1;
      8'h7e: data = 'h290074;
      8'h7f: data = 'h6005d;
      default: data = 'h0;
    endcase
            
endmodule // top$pipeline$control$weights$1
